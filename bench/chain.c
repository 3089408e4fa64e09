// SPDX-License-Identifier: BSD-3-Clause
//
// chain.c -- bench scene: a chain of capsules on ball joints, hanging from the world by its
// first link, released horizontal.
//
// `chain links=100 steps=300 stepper=world|quick iterations=20`: links 10 cm long (capsule
// radius 2.5 cm, cylinder 5 cm, 0.1 kg), along +x from the world anchor at the origin, dt 1/100,
// gravity 9.81, world ERP and CFM left at their defaults. The capsules are in a hash space and
// collide with each other (mu 0.8, dContactApprox1, 4 contacts per pair) except where a joint
// connects them; there is no ground. `seed=N` releases the chain tilted down by a random angle
// of at most 2 degrees instead (another sample of this chaotic motion). `position_iterations=N`
// (this project only) adds N sweeps of its opt-in position correction after each step.
// Quality: the largest anchor-to-anchor2 distance of any joint over the run (joint_sep), the
// same at the end (joint_sep_end) and averaged over the steps (joint_sep_mean: steadier than
// a maximum), the deepest contact seen, and the kinetic energy at the end.

#include "bench_ode.h"

#define LINK 0.1
#define RADIUS 0.025
#define MASS 0.1

int main(int argc, char **argv)
{
    bench_args args = bench_args_init(argc, argv);
    const int links = (int)bench_arg_int(&args, "links", 100);
    const int steps = (int)bench_arg_int(&args, "steps", 300);
    const int iterations = (int)bench_arg_int(&args, "iterations", 20);
    const bench_stepper stepper = bench_arg_stepper(&args, "world");
    const long seed = bench_arg_int(&args, "seed", 0);   // 0: not given, horizontal
    const int position_iterations = bench_arg_position_iterations(&args);
    bench_args_check(&args,
                     "[links=N] [steps=N] [stepper=world|quick|fast] [iterations=N] [seed=N] "
                     "[position_iterations=N]");
    const dReal dt = (dReal)(1.0 / 100.0);

    dInitODE2(0);
    dWorldID world = dWorldCreate();
    dWorldSetGravity(world, 0, 0, (dReal)-9.81);
    dWorldSetQuickStepNumIterations(world, iterations);
    bench_set_position_iterations(world, position_iterations);
    dSpaceID space = dHashSpaceCreate(0);

    dBodyID *body = (dBodyID *)malloc(sizeof(dBodyID) * (size_t)links);
    dJointID *joint = (dJointID *)malloc(sizeof(dJointID) * (size_t)links);
    if (!body || !joint) return 1;
    dMass m;
    // The capsule's axis is the body's z; turning the body about y makes it the world's x
    // (tilted down by `tilt` radians).
    dMassSetCapsuleTotal(&m, (dReal)MASS, 3, (dReal)RADIUS, (dReal)(LINK - 2 * RADIUS));
    bench_rng rng = bench_rng_init((unsigned long long)seed);
    const double tilt = seed ? bench_rand(&rng, 0, 2 * M_PI / 180) : 0;
    const double dx = cos(tilt), dz = seed ? -sin(tilt) : 0;   // +0 without a seed, as before
    dMatrix3 R;
    dRFromAxisAndAngle(R, 0, 1, 0, (dReal)(M_PI / 2 + tilt));
    for (int i = 0; i < links; i++) {
        body[i] = dBodyCreate(world);
        dBodySetMass(body[i], &m);
        const double along = (i + 0.5) * LINK;
        dBodySetPosition(body[i], (dReal)(along * dx), 0, (dReal)(along * dz));
        dBodySetRotation(body[i], R);
        dGeomID g = dCreateCapsule(space, (dReal)RADIUS, (dReal)(LINK - 2 * RADIUS));
        dGeomSetBody(g, body[i]);
        joint[i] = dJointCreateBall(world, 0);
        dJointAttach(joint[i], body[i], i > 0 ? body[i - 1] : 0);
        dJointSetBallAnchor(joint[i], (dReal)(i * LINK * dx), 0, (dReal)(i * LINK * dz));
    }

    bench_contacts con;
    bench_contacts_init(&con, world);
    con.skip_connected = 1;
    double coll_s = 0, step_s = 0, sep_max = 0, sep_end = 0, sep_sum = 0;
    for (int s = 0; s < steps; s++) {
        bench_timed_step(space, &con, stepper, dt, iterations, &coll_s, &step_s);
        sep_end = 0;
        for (int i = 0; i < links; i++) {
            double d = bench_joint_separation(joint[i]);
            if (d > sep_end) sep_end = d;
        }
        if (sep_end > sep_max) sep_max = sep_end;
        sep_sum += sep_end;
    }

    double ke = 0;
    for (int i = 0; i < links; i++) ke += bench_body_ke(body[i]);
    const dReal *tip = dBodyGetPosition(body[links - 1]);
    bench_report("chain", BENCH_ENGINE, bench_stepper_name(stepper), links, steps, coll_s, step_s,
                 "iterations=%d position_iterations=%d max_pen=%.6f joint_sep=%.6f "
                 "joint_sep_end=%.6f joint_sep_mean=%.6f ke_end=%.6g tip_z=%.4f "
                 "contacts_per_step=%.1f",
                 iterations, position_iterations, con.max_depth, sep_max, sep_end, sep_sum / steps,
                 ke, (double)tip[2], (double)con.contacts / steps);

    dJointGroupDestroy(con.group);
    dSpaceDestroy(space);
    dWorldDestroy(world);
    dCloseODE();
    free(body);
    free(joint);
    return 0;
}
