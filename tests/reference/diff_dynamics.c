// SPDX-License-Identifier: BSD-3-Clause
//
// diff_dynamics.c -- the same simulations run against this library and the
// reference ODE 0.16: dWorldStep on free fall, a hinge pendulum, a released
// ball-joint chain, a motor, a stop and joint feedback. Bodies are spheres
// (no gyroscopic effect, whose integration differs on purpose: ours is
// implicit and does not lose energy). Tolerances: 1e-6 m or rad after
// hundreds of steps; both are the same first-order method with a direct
// solver, so they agree to rounding unless a solver takes another path.

#include "diff_print.h"

static dBodyID sphere_body(dWorldID w, dReal mass, dReal x, dReal y, dReal z)
{
    dBodyID b = dBodyCreate(w);
    dMass m;
    dMassSetSphereTotal(&m, mass, 0.05);
    dBodySetMass(b, &m);
    dBodySetPosition(b, x, y, z);
    return b;
}

static void free_fall(void)
{
    dWorldID w = dWorldCreate();
    dWorldSetGravity(w, 0, 0, -9.81);
    dBodyID b = sphere_body(w, 1, 0, 0, 10);
    dBodySetLinearVel(b, 1, 0, 2);
    for (int i = 0; i < 250; i++) dWorldStep(w, 0.004);
    diff_values("free_fall_pos", 1e-9, dBodyGetPosition(b), 3);
    diff_values("free_fall_vel", 1e-9, dBodyGetLinearVel(b), 3);
    dWorldDestroy(w);
}

static void hinge_pendulum(void)
{
    dWorldID w = dWorldCreate();
    dWorldSetGravity(w, 0, 0, -9.81);
    dBodyID b = sphere_body(w, 2, 0.6, 0, -0.8);
    dJointID j = dJointCreateHinge(w, 0);
    dJointAttach(j, b, 0);
    dJointSetHingeAnchor(j, 0, 0, 0);
    dJointSetHingeAxis(j, 0, 1, 0);
    for (int i = 0; i < 500; i++) dWorldStep(w, 0.005);
    diff_values("hinge_pendulum_pos", 1e-6, dBodyGetPosition(b), 3);
    diff_value("hinge_pendulum_angle", 1e-6, dJointGetHingeAngle(j));
    diff_value("hinge_pendulum_rate", 1e-5, dJointGetHingeAngleRate(j));
    dWorldDestroy(w);
}

static void released_chain(void)
{
    enum { LINKS = 12 };
    dWorldID w = dWorldCreate();
    dWorldSetGravity(w, 0, 0, -9.81);
    dBodyID body[LINKS];
    dJointID joint[LINKS];
    for (int i = 0; i < LINKS; i++) {
        body[i] = sphere_body(w, 0.1, (i + 1) * 0.1, 0, 0);
        joint[i] = dJointCreateBall(w, 0);
        dJointAttach(joint[i], body[i], i ? body[i - 1] : 0);
        dJointSetBallAnchor(joint[i], i * 0.1, 0, 0);
    }
    double worst = 0;
    for (int s = 0; s < 300; s++) {
        dWorldStep(w, 0.01);
        for (int i = 0; i < LINKS; i++) {
            dVector3 a, b;
            dJointGetBallAnchor(joint[i], a);
            dJointGetBallAnchor2(joint[i], b);
            double e = dCalcPointsDistance3(a, b);
            if (e > worst) worst = e;
        }
    }
    diff_value("chain_worst_joint_error", 1e-6, worst);
    diff_values("chain_tip_pos", 1e-5, dBodyGetPosition(body[LINKS - 1]), 3);
    dWorldDestroy(w);
}

static void motor_and_stop(void)
{
    dWorldID w = dWorldCreate();
    dBodyID b = sphere_body(w, 1, 0, 0, 0);
    dJointID j = dJointCreateHinge(w, 0);
    dJointAttach(j, b, 0);
    dJointSetHingeAnchor(j, 0, 0, 0);
    dJointSetHingeAxis(j, 0, 0, 1);
    dJointSetHingeParam(j, dParamVel, 3);
    dJointSetHingeParam(j, dParamFMax, 0.05);
    dJointSetHingeParam(j, dParamHiStop, 0.4);
    for (int i = 0; i < 200; i++) dWorldStep(w, 0.01);
    diff_value("motor_stop_angle", 1e-6, dJointGetHingeAngle(j));
    diff_value("motor_stop_rate", 1e-6, dJointGetHingeAngleRate(j));
    dWorldDestroy(w);
}

static void feedback(void)
{
    dWorldID w = dWorldCreate();
    dWorldSetGravity(w, 0, 0, -9.81);
    dBodyID b = sphere_body(w, 3, 0.5, 0, 0);
    dJointID j = dJointCreateBall(w, 0);
    dJointAttach(j, b, 0);
    dJointSetBallAnchor(j, 0, 0, 0);
    dJointFeedback fb;
    dJointSetFeedback(j, &fb);
    for (int i = 0; i < 20; i++) dWorldStep(w, 0.01);
    diff_values("ball_feedback_f1", 1e-6, fb.f1, 3);
    diff_values("ball_feedback_t1", 1e-6, fb.t1, 3);
    dWorldDestroy(w);
}

int main(void)
{
    dInitODE();
    free_fall();
    hinge_pendulum();
    released_chain();
    motor_and_stop();
    feedback();
    dCloseODE();
    return 0;
}
