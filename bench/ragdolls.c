// SPDX-License-Identifier: BSD-3-Clause
//
// ragdolls.c -- bench scene: jointed figures dropped in a heap on a plane.
//
// `ragdolls figures=40 steps=600 stepper=quick|world iterations=20 seed=40`: each figure has
// 11 bodies (box pelvis and chest, sphere head, capsule limbs; 65 kg) and 10 joints: universal
// joints with limits for the spine and the hips, hinges with limits for elbows and knees, ball
// joints for the neck and the shoulders. Figures stand in two layers of a 5 x 4 grid, 2.2 m
// apart, the second layer 2.2 m above the first, each turned by a random rotation (drawn from
// `seed`) about its middle. Hash space, 4 contacts per pair, mu 0.8 with dContactApprox1,
// dt 1/60, gravity 9.81, world ERP and CFM left at their defaults; parts of one figure do not
// collide with each other. `position_iterations=N` (this project only) adds N sweeps of its
// opt-in position correction after each step; `gyroscopic=off` steps every body without the
// gyroscopic term (dBodySetGyroscopicMode), to compare the engines' steps without it.
// Quality: the largest anchor-to-anchor2 distance of any joint over the run (joint_sep), at the
// end and averaged over the steps (joint_sep_mean: steadier than a maximum), the deepest
// contact seen (max_pen: a falling limb's first touch of the ground, as deep as the limb got
// in the step before the collision saw it), and the kinetic energy at the end.

#include "bench_ode.h"

#define PARTS 11
#define JOINTS 10
#define SPACING 2.2
#define MIDDLE 0.9  // height of the point figures turn about, in the figure's frame

enum { BOX, SPHERE, CAPSULE };

// A body of the figure standing upright, feet at z = 0, facing -y.
typedef struct part {
    int shape;
    double size[3];  // box: lengths; sphere: radius; capsule: radius, cylinder length (along z)
    double mass;
    double pos[3];
} part;

static const part parts[PARTS] = {
    {BOX, {0.32, 0.20, 0.20}, 10.0, {0, 0, 1.00}},         // 0 pelvis
    {BOX, {0.38, 0.22, 0.45}, 20.0, {0, 0, 1.35}},         // 1 chest
    {SPHERE, {0.11, 0, 0}, 5.0, {0, 0, 1.72}},             // 2 head
    {CAPSULE, {0.05, 0.20, 0}, 2.5, {0.26, 0, 1.40}},      // 3 upper arms
    {CAPSULE, {0.05, 0.20, 0}, 2.5, {-0.26, 0, 1.40}},     // 4
    {CAPSULE, {0.045, 0.21, 0}, 1.5, {0.26, 0, 1.10}},     // 5 forearms
    {CAPSULE, {0.045, 0.21, 0}, 1.5, {-0.26, 0, 1.10}},    // 6
    {CAPSULE, {0.07, 0.30, 0}, 8.0, {0.10, 0, 0.70}},      // 7 thighs
    {CAPSULE, {0.07, 0.30, 0}, 8.0, {-0.10, 0, 0.70}},     // 8
    {CAPSULE, {0.06, 0.34, 0}, 4.0, {0.10, 0, 0.25}},      // 9 shins
    {CAPSULE, {0.06, 0.34, 0}, 4.0, {-0.10, 0, 0.25}},     // 10
};

typedef struct link {
    int type;  // dJointTypeBall, dJointTypeHinge or dJointTypeUniversal
    int a, b;
    double anchor[3];
    double lo1, hi1, lo2, hi2;  // stops; axis 1 is x, axis 2 (universal) is y
} link;

static const link links[JOINTS] = {
    {dJointTypeUniversal, 0, 1, {0, 0, 1.10}, -0.6, 0.6, -0.4, 0.4},      // spine
    {dJointTypeBall, 1, 2, {0, 0, 1.60}, 0, 0, 0, 0},                     // neck
    {dJointTypeBall, 1, 3, {0.26, 0, 1.55}, 0, 0, 0, 0},                  // shoulders
    {dJointTypeBall, 1, 4, {-0.26, 0, 1.55}, 0, 0, 0, 0},
    {dJointTypeHinge, 3, 5, {0.26, 0, 1.25}, -2.5, 0, 0, 0},              // elbows
    {dJointTypeHinge, 4, 6, {-0.26, 0, 1.25}, -2.5, 0, 0, 0},
    {dJointTypeUniversal, 0, 7, {0.10, 0, 0.92}, -1.6, 0.4, -0.6, 0.6},   // hips
    {dJointTypeUniversal, 0, 8, {-0.10, 0, 0.92}, -1.6, 0.4, -0.6, 0.6},
    {dJointTypeHinge, 7, 9, {0.10, 0, 0.48}, 0, 2.5, 0, 0},               // knees
    {dJointTypeHinge, 8, 10, {-0.10, 0, 0.48}, 0, 2.5, 0, 0},
};

// Build figure f turned by Rf about its middle, the middle placed at t.
static void make_figure(dWorldID world, dSpaceID space, int f, const dMatrix3 Rf, const dReal *t,
                        dBodyID *body, dJointID *joint)
{
    for (int i = 0; i < PARTS; i++) {
        const part *p = &parts[i];
        dMass m;
        dGeomID g;
        if (p->shape == BOX) {
            dMassSetBoxTotal(&m, (dReal)p->mass, (dReal)p->size[0], (dReal)p->size[1],
                             (dReal)p->size[2]);
            g = dCreateBox(space, (dReal)p->size[0], (dReal)p->size[1], (dReal)p->size[2]);
        } else if (p->shape == SPHERE) {
            dMassSetSphereTotal(&m, (dReal)p->mass, (dReal)p->size[0]);
            g = dCreateSphere(space, (dReal)p->size[0]);
        } else {
            dMassSetCapsuleTotal(&m, (dReal)p->mass, 3, (dReal)p->size[0], (dReal)p->size[1]);
            g = dCreateCapsule(space, (dReal)p->size[0], (dReal)p->size[1]);
        }
        body[i] = dBodyCreate(world);
        dBodySetMass(body[i], &m);
        dVector3 pos;
        bench_xform(pos, Rf, t, p->pos[0], p->pos[1], p->pos[2] - MIDDLE);
        dBodySetPosition(body[i], pos[0], pos[1], pos[2]);
        dBodySetRotation(body[i], Rf);
        dGeomSetBody(g, body[i]);
        dGeomSetData(g, (void *)(intptr_t)(f + 1));
    }
    for (int i = 0; i < JOINTS; i++) {
        const link *l = &links[i];
        dVector3 anchor, x, y;
        bench_xform(anchor, Rf, t, l->anchor[0], l->anchor[1], l->anchor[2] - MIDDLE);
        bench_xform(x, Rf, NULL, 1, 0, 0);
        bench_xform(y, Rf, NULL, 0, 1, 0);
        dJointID j;
        if (l->type == dJointTypeBall) {
            j = dJointCreateBall(world, 0);
            dJointAttach(j, body[l->a], body[l->b]);
            dJointSetBallAnchor(j, anchor[0], anchor[1], anchor[2]);
        } else if (l->type == dJointTypeHinge) {
            j = dJointCreateHinge(world, 0);
            dJointAttach(j, body[l->a], body[l->b]);
            dJointSetHingeAnchor(j, anchor[0], anchor[1], anchor[2]);
            dJointSetHingeAxis(j, x[0], x[1], x[2]);
            dJointSetHingeParam(j, dParamLoStop, (dReal)l->lo1);
            dJointSetHingeParam(j, dParamHiStop, (dReal)l->hi1);
        } else {
            j = dJointCreateUniversal(world, 0);
            dJointAttach(j, body[l->a], body[l->b]);
            dJointSetUniversalAnchor(j, anchor[0], anchor[1], anchor[2]);
            dJointSetUniversalAxis1(j, x[0], x[1], x[2]);
            dJointSetUniversalAxis2(j, y[0], y[1], y[2]);
            dJointSetUniversalParam(j, dParamLoStop, (dReal)l->lo1);
            dJointSetUniversalParam(j, dParamHiStop, (dReal)l->hi1);
            dJointSetUniversalParam(j, dParamLoStop2, (dReal)l->lo2);
            dJointSetUniversalParam(j, dParamHiStop2, (dReal)l->hi2);
        }
        joint[i] = j;
    }
}

int main(int argc, char **argv)
{
    bench_args args = bench_args_init(argc, argv);
    const int figures = (int)bench_arg_int(&args, "figures", 40);
    const int steps = (int)bench_arg_int(&args, "steps", 600);
    const int iterations = (int)bench_arg_int(&args, "iterations", 20);
    const bench_stepper stepper = bench_arg_stepper(&args, "quick");
    const long seed = bench_arg_int(&args, "seed", 40);
    const int position_iterations = bench_arg_position_iterations(&args);
    const char *gyroscopic = bench_arg_str(&args, "gyroscopic", "on");
    if (strcmp(gyroscopic, "on") != 0 && strcmp(gyroscopic, "off") != 0) {
        fprintf(stderr, "%s: gyroscopic is on or off, not '%s'\n", argv[0], gyroscopic);
        return 2;
    }
    bench_threads threads;
    const dReal dt = (dReal)(1.0 / 60.0);

    dInitODE2(0);
    dWorldID world = dWorldCreate();
    bench_threads_start(&threads, &args, world, bench_stepper_name(stepper));
    bench_args_check(&args,
                     "[figures=N] [steps=N] [stepper=quick|world|fast] [iterations=N] [threads=N] "
                     "[seed=N] [position_iterations=N] [gyroscopic=on|off]");
    dWorldSetGravity(world, 0, 0, (dReal)-9.81);
    dWorldSetQuickStepNumIterations(world, iterations);
    bench_set_position_iterations(world, position_iterations);
    dSpaceID space = dHashSpaceCreate(0);
    dCreatePlane(space, 0, 0, 1, 0);

    dBodyID *body = (dBodyID *)malloc(sizeof(dBodyID) * (size_t)(figures * PARTS));
    dJointID *joint = (dJointID *)malloc(sizeof(dJointID) * (size_t)(figures * JOINTS));
    if (!body || !joint) return 1;
    bench_rng rng = bench_rng_init((unsigned long long)seed);
    for (int f = 0; f < figures; f++) {
        const int layer = f / 20, cell = f % 20;
        dReal t[3] = {(dReal)((cell % 5 - 2) * SPACING), (dReal)((cell / 5 - 1.5) * SPACING),
                      (dReal)(1.2 + layer * SPACING)};
        double ax = bench_rand(&rng, -1, 1), ay = bench_rand(&rng, -1, 1);
        double az = bench_rand(&rng, -1, 1), angle = bench_rand(&rng, 0, 2 * M_PI);
        dMatrix3 Rf;
        dRFromAxisAndAngle(Rf, (dReal)ax, (dReal)ay, (dReal)az, (dReal)angle);
        make_figure(world, space, f, Rf, t, body + f * PARTS, joint + f * JOINTS);
        if (strcmp(gyroscopic, "off") == 0)
            for (int i = 0; i < PARTS; i++) dBodySetGyroscopicMode(body[f * PARTS + i], 0);
    }

    bench_contacts con;
    bench_contacts_init(&con, world);
    con.skip_same_data = 1;
    double coll_s = 0, step_s = 0, sep_max = 0, sep_end = 0, sep_sum = 0;
    for (int s = 0; s < steps; s++) {
        bench_timed_step(space, &con, stepper, dt, iterations, &coll_s, &step_s);
        sep_end = 0;
        for (int i = 0; i < figures * JOINTS; i++) {
            double d = bench_joint_separation(joint[i]);
            if (d > sep_end) sep_end = d;
        }
        if (sep_end > sep_max) sep_max = sep_end;
        sep_sum += sep_end;
    }

    double ke = 0, mass = 0;
    for (int i = 0; i < figures * PARTS; i++) {
        dMass m;
        dBodyGetMass(body[i], &m);
        ke += bench_body_ke(body[i]);
        mass += m.mass;
    }
    bench_report("ragdolls", BENCH_ENGINE, threads.variant, figures * PARTS, steps,
                 coll_s, step_s,
                 "iterations=%d position_iterations=%d gyroscopic=%s max_pen=%.6f joint_sep=%.6f "
                 "joint_sep_end=%.6f joint_sep_mean=%.6f ke_end=%.6g ke_per_kg_end=%.6g "
                 "contacts_per_step=%.1f",
                 iterations, position_iterations, gyroscopic, con.max_depth, sep_max, sep_end,
                 sep_sum / steps, ke, ke / mass, (double)con.contacts / steps);

    dJointGroupDestroy(con.group);
    dSpaceDestroy(space);
    bench_threads_stop(&threads, world);
    dWorldDestroy(world);
    dCloseODE();
    free(body);
    free(joint);
    return 0;
}
