// scene_program.c -- a small deterministic ODE scene, written against the ODE
// API only (so it builds against the reference ODE too): a sphere thrown onto
// a plane, sliding with friction into rolling, and a hinge pendulum released
// horizontally. check_install.sh builds it every way a program is built
// (ode-config, static archives, CMake, and against the reference to run on our
// libode.so.8) and compares what it prints. Each line is
//   name tolerance value value ...
// It exits non-zero when the physics is wrong: the sphere must end resting on
// the plane and rolling without slipping (v = w r), the pendulum must keep its
// length and swing through the bottom.
#include <ode/ode.h>
#include <math.h>
#include <stdio.h>

#define RADIUS 0.5
#define MAX_CONTACTS 4

static dWorldID world;
static dJointGroupID contacts;

// The plane and the sphere touching: friction pyramid, no bounce.
static void near_callback(void *data, dGeomID a, dGeomID b)
{
    (void)data;
    dContact c[MAX_CONTACTS];
    int n = dCollide(a, b, MAX_CONTACTS, &c[0].geom, sizeof c[0]);
    for (int i = 0; i < n; i++) {
        c[i].surface.mode = dContactApprox1;
        c[i].surface.mu = 0.4;
        dJointID j = dJointCreateContact(world, contacts, &c[i]);
        dJointAttach(j, dGeomGetBody(a), dGeomGetBody(b));
    }
}

static void print_line(const char *name, double tol, const double *v, int n)
{
    printf("%s %g", name, tol);
    for (int i = 0; i < n; i++) printf(" %.6f", v[i]);
    printf("\n");
}

int main(void)
{
    dInitODE2(0);
    world = dWorldCreate();
    dWorldSetGravity(world, 0, 0, -9.81);
    dWorldSetERP(world, 0.2);
    dWorldSetCFM(world, 1e-5);
    dSpaceID space = dSimpleSpaceCreate(0);
    contacts = dJointGroupCreate(0);
    dCreatePlane(space, 0, 0, 1, 0);

    dMass m;
    dBodyID ball = dBodyCreate(world);
    dMassSetSphereTotal(&m, 1, RADIUS);
    dBodySetMass(ball, &m);
    dBodySetPosition(ball, 0, 0, 1.5);
    dBodySetLinearVel(ball, 2, 0, 0);
    dGeomSetBody(dCreateSphere(space, RADIUS), ball);

    dBodyID bob = dBodyCreate(world);
    dMassSetBoxTotal(&m, 1, 0.1, 0.1, 0.1);
    dBodySetMass(bob, &m);
    dBodySetPosition(bob, 1, 5, 3);
    dJointID hinge = dJointCreateHinge(world, 0);
    dJointAttach(hinge, bob, 0);
    dJointSetHingeAnchor(hinge, 0, 5, 3);
    dJointSetHingeAxis(hinge, 0, 1, 0);

    double lowest = 3, length_error = 0;
    for (int step = 1; step <= 300; step++) {
        dSpaceCollide(space, 0, near_callback);
        dWorldStep(world, 0.01);
        dJointGroupEmpty(contacts);
        const dReal *p = dBodyGetPosition(bob);
        double len = sqrt(p[0] * p[0] + (p[2] - 3) * (p[2] - 3));
        if (fabs(len - 1) > length_error) length_error = fabs(len - 1);
        if (p[2] < lowest) lowest = p[2];
        if (step % 50 == 0) {
            const dReal *q = dBodyGetPosition(ball), *v = dBodyGetLinearVel(ball);
            const dReal *w = dBodyGetAngularVel(ball);
            double s[] = { q[0], q[2], v[0], v[2], w[1] };
            char name[32];
            snprintf(name, sizeof name, "sphere_%d", step);
            print_line(name, 2e-3, s, 5);
            double h[] = { dJointGetHingeAngle(hinge), dJointGetHingeAngleRate(hinge), p[0],
                           p[2] };
            snprintf(name, sizeof name, "pendulum_%d", step);
            print_line(name, 2e-3, h, 4);
        }
    }
    const dReal *q = dBodyGetPosition(ball), *v = dBodyGetLinearVel(ball);
    const dReal *w = dBodyGetAngularVel(ball);
    int resting = fabs(q[2] - RADIUS) < 0.01 && fabs(v[2]) < 0.01;
    int rolling = v[0] > 0 && fabs(v[0] - w[1] * RADIUS) < 0.01;
    int swinging = length_error < 0.01 && lowest < 2.01;   // drift held by ERP
    dSpaceDestroy(space);
    dJointGroupDestroy(contacts);
    dWorldDestroy(world);
    dCloseODE();
    if (!resting || !rolling || !swinging) {
        printf("wrong: resting %d rolling %d swinging %d\n", resting, rolling, swinging);
        return 1;
    }
    return 0;
}
