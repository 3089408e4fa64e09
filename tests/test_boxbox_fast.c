// SPDX-License-Identifier: BSD-3-Clause
//
// test_boxbox_fast.c -- the box-box collider's fast paths (unrolled axes,
// the edge axes' bound, the rectangle clipper, the exits' bounds, the
// clearance in fours) against the plain collider of boxbox_slow.h: over
// random poses, resting stacks (aligned, slightly tilted, turned by right
// angles, one box across two), crossed edges and deep overlaps, in both
// orders, through dBoxBox and through dCollide (twice, so the remembered
// axis is used), for every contact count, dBoxBox with any matrices and
// sides, and poses within rounding of the ties between axes; the contacts
// must be the same to the bit.

#include "boxbox_slow.h"
#include "test.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

static unsigned long long rng = 0x9e3779b97f4a7c15ull;

// Uniform in [lo, hi).
static double rnd(double lo, double hi)
{
    rng = rng * 6364136223846793005ull + 1442695040888963407ull;
    return lo + (hi - lo) * (double)(rng >> 11) / 9007199254740992.0;
}

// The rotation by angle about the unit axis u (Rodrigues).
static void rotation(dMatrix3 R, const double u[3], double angle)
{
    double c = cos(angle), s = sin(angle), t = 1 - c, x = u[0], y = u[1], z = u[2];
    double M[12] = { t * x * x + c, t * x * y - s * z, t * x * z + s * y, 0,
                     t * x * y + s * z, t * y * y + c, t * y * z - s * x, 0,
                     t * x * z - s * y, t * y * z + s * x, t * z * z + c, 0 };
    for (int i = 0; i < 12; i++) R[i] = (dReal)M[i];
}

// A random axis, turned by angle.
static void random_tilt(dMatrix3 R, double angle)
{
    double u[3], l = 0;
    do {
        l = 0;
        for (int i = 0; i < 3; i++) {
            u[i] = rnd(-1, 1);
            l += u[i] * u[i];
        }
    } while (l < 1e-4 || l > 1);
    l = sqrt(l);
    for (int i = 0; i < 3; i++) u[i] /= l;
    rotation(R, u, angle);
}

// A random rotation: a random axis and angle.
static void random_rotation(dMatrix3 R)
{
    random_tilt(R, rnd(-M_PI, M_PI));
}

// R = A B.
static void mul(dMatrix3 R, const dMatrix3 A, const dMatrix3 B)
{
    for (int i = 0; i < 3; i++) {
        for (int j = 0; j < 3; j++)
            R[4 * i + j] = A[4 * i] * B[j] + A[4 * i + 1] * B[4 + j] + A[4 * i + 2] * B[8 + j];
        R[4 * i + 3] = 0;
    }
}

// A turn by a multiple of a right angle about axis k (0-2), exact.
static void right_angles(dMatrix3 R, int k, int quarters)
{
    static const int c4[4] = { 1, 0, -1, 0 }, s4[4] = { 0, 1, 0, -1 };
    int c = c4[quarters & 3], s = s4[quarters & 3], k1 = (k + 1) % 3, k2 = (k + 2) % 3;
    memset(R, 0, sizeof(dMatrix3));
    R[4 * k + k] = 1;
    R[4 * k1 + k1] = (dReal)c;
    R[4 * k2 + k2] = (dReal)c;
    R[4 * k1 + k2] = (dReal)-s;
    R[4 * k2 + k1] = (dReal)s;
}

// One pose of two boxes.
typedef struct pose {
    dVector3 p[2], side[2];
    dMatrix3 R[2];
} pose;

// Coverage of the cases the comparisons met.
typedef struct tally {
    int pairs, touching, face, edge, many, culled;
} tally;

// Whether the two contact lists are the same to the bit.
static int same_contacts(const dContactGeom *a, const dContactGeom *b, int n)
{
    for (int i = 0; i < n; i++) {
        if (memcmp(a[i].pos, b[i].pos, 3 * sizeof(dReal)) != 0) return 0;
        if (memcmp(a[i].normal, b[i].normal, 3 * sizeof(dReal)) != 0) return 0;
        if (memcmp(&a[i].depth, &b[i].depth, sizeof(dReal)) != 0) return 0;
        if (a[i].g1 != b[i].g1 || a[i].g2 != b[i].g2) return 0;
        if (a[i].side1 != b[i].side1 || a[i].side2 != b[i].side2) return 0;
    }
    return 1;
}

static void print_pose(const pose *ps)
{
    for (int k = 0; k < 2; k++) {
        fprintf(stderr, "# box %d p (%.17g %.17g %.17g) side (%.17g %.17g %.17g)\n# R", k,
                (double)ps->p[k][0], (double)ps->p[k][1], (double)ps->p[k][2],
                (double)ps->side[k][0], (double)ps->side[k][1], (double)ps->side[k][2]);
        for (int i = 0; i < 12; i++) fprintf(stderr, " %.17g", (double)ps->R[k][i]);
        fprintf(stderr, "\n");
    }
}

// dBoxBox against slow_box_box on box u then box 1 - u, every contact count
// 1-8: 0 when the same, else 1 (the pose printed).
static int check_dboxbox(const pose *ps, int u, tally *t)
{
    int v = 1 - u;
    for (int max = 1; max <= 8; max++) {
        dContactGeom fast[8], slow[8];
        memset(fast, 0, sizeof fast);
        memset(slow, 0, sizeof slow);
        dVector3 nf = { 0, 0, 0, 0 };
        dReal ns[3] = { 0, 0, 0 }, df = 0, ds = 0;
        int cf = -1, cs = -1;
        int n = dBoxBox(ps->p[u], ps->R[u], ps->side[u], ps->p[v], ps->R[v], ps->side[v], nf,
                        &df, &cf, max, fast, sizeof(dContactGeom));
        int m = slow_box_box(ps->p[u], ps->R[u], ps->side[u], ps->p[v], ps->R[v], ps->side[v],
                             0, 0, max, slow, sizeof(dContactGeom), ns, &ds, &cs);
        int ok = n == m && same_contacts(fast, slow, n);
        if (ok && n > 0) {
            ok = cf == cs + 1 && df == ds;
            for (int q = 0; q < 3; q++) ok = ok && nf[q] == -ns[q];
        }
        if (!ok) {
            fprintf(stderr, "# dBoxBox differs (order %d, max %d): %d contacts against %d, "
                    "code %d against %d\n", u, max, n, m, cf, cs + 1);
            for (int i = 0; i < n || i < m; i++)
                fprintf(stderr, "#  %d: fast (%.17g %.17g %.17g) %.17g  slow (%.17g %.17g %.17g) "
                        "%.17g\n", i, (double)fast[i].pos[0], (double)fast[i].pos[1],
                        (double)fast[i].pos[2], (double)fast[i].depth, (double)slow[i].pos[0],
                        (double)slow[i].pos[1], (double)slow[i].pos[2], (double)slow[i].depth);
            print_pose(ps);
            return 1;
        }
        if (max == 8) {
            t->pairs++;
            if (n > 0) {
                t->touching++;
                if (cs < 6) t->face++;
                else t->edge++;
                if (n > 4) t->many++;
            }
        }
        if (max == 4 && n == 4) {
            dContactGeom all[8];
            dReal nn[3], dd;
            int cc;
            if (slow_box_box(ps->p[u], ps->R[u], ps->side[u], ps->p[v], ps->R[v], ps->side[v], 0,
                             0, 8, all, sizeof(dContactGeom), nn, &dd, &cc) > 4)
                t->culled++;
        }
    }
    return 0;
}

// dCollide on two box geoms in both orders, twice each (the second call
// tries the axis remembered by the first), against slow_box_box, with a
// contact stride wider than dContactGeom.
static int check_dcollide(const pose *ps)
{
    typedef struct wide {
        dContactGeom c;
        double pad[3];
    } wide;
    dGeomID g[2];
    for (int k = 0; k < 2; k++) {
        g[k] = dCreateBox(0, ps->side[k][0], ps->side[k][1], ps->side[k][2]);
        dGeomSetPosition(g[k], ps->p[k][0], ps->p[k][1], ps->p[k][2]);
        dGeomSetRotation(g[k], ps->R[k]);
    }
    pose gp;   // as the geoms hold it (dGeomSetRotation cleans the rotation)
    for (int k = 0; k < 2; k++) {
        memcpy(gp.p[k], dGeomGetPosition(g[k]), sizeof(dVector3));
        memcpy(gp.R[k], dGeomGetRotation(g[k]), sizeof(dMatrix3));
        dGeomBoxGetLengths(g[k], gp.side[k]);
    }
    ps = &gp;
    int bad = 0;
    for (int round = 0; round < 4 && !bad; round++) {
        int u = round & 1, v = 1 - u, max = round < 2 ? 8 : 3;
        wide fast[8], slow[8];
        memset(fast, 0, sizeof fast);
        memset(slow, 0, sizeof slow);
        dReal nn[3], dd;
        int cc;
        int n = dCollide(g[u], g[v], max, &fast[0].c, sizeof(wide));
        int m = slow_box_box(ps->p[u], ps->R[u], ps->side[u], ps->p[v], ps->R[v], ps->side[v],
                             g[u], g[v], max, &slow[0].c, sizeof(wide), nn, &dd, &cc);
        bad = n != m;
        for (int i = 0; i < n && !bad; i++) bad = !same_contacts(&fast[i].c, &slow[i].c, 1);
        if (bad) {
            fprintf(stderr, "# dCollide differs (order %d, round %d): %d against %d\n", u, round,
                    n, m);
            print_pose(ps);
        }
    }
    dGeomDestroy(g[0]);
    dGeomDestroy(g[1]);
    return bad;
}

static int check_pose(const pose *ps, tally *t, int with_geoms)
{
    if (check_dboxbox(ps, 0, t) || check_dboxbox(ps, 1, t)) return 1;
    return with_geoms ? check_dcollide(ps) : 0;
}

static void set_vec(dVector3 v, double x, double y, double z)
{
    v[0] = (dReal)x;
    v[1] = (dReal)y;
    v[2] = (dReal)z;
    v[3] = 0;
}

static void random_sides(dVector3 s, double lo, double hi)
{
    set_vec(s, rnd(lo, hi), rnd(lo, hi), rnd(lo, hi));
}

// Random sizes, rotations and offsets within the bounding spheres' reach:
// apart, touching at faces, edges and corners, deep.
static int test_random_poses(void)
{
    tally t = { 0 };
    for (int it = 0; it < 20000; it++) {
        pose ps;
        double reach = 0;
        for (int k = 0; k < 2; k++) {
            random_sides(ps.side[k], 0.05, 2);
            random_rotation(ps.R[k]);
            reach += 0.5 * sqrt((double)(ps.side[k][0] * ps.side[k][0] +
                                         ps.side[k][1] * ps.side[k][1] +
                                         ps.side[k][2] * ps.side[k][2]));
        }
        set_vec(ps.p[0], rnd(-1, 1), rnd(-1, 1), rnd(-1, 1));
        double f = rnd(0, 1) * reach;
        set_vec(ps.p[1], ps.p[0][0] + rnd(-f, f), ps.p[0][1] + rnd(-f, f),
                ps.p[0][2] + rnd(-f, f));
        if (check_pose(&ps, &t, it % 10 == 0)) return 1;
    }
    printf("# random: %d pairs, %d touching (%d face, %d edge), %d with over 4 points, %d "
           "culled\n", t.pairs, t.touching, t.face, t.edge, t.many, t.culled);
    CHECK(t.face > 2000 && t.edge > 500 && t.many > 100 && t.culled > 100);
    return 0;
}

// Box 1 resting on box 0 (sides along z): centred anywhere over its top,
// penetrating by up to 1 % of its height, tilted by up to tilt radians, as
// the pyramids' boxes are step after step; some turned about z by right
// angles or at random, some exactly aligned.
static int resting_case(double tilt, int turn, tally *t)
{
    pose ps;
    random_sides(ps.side[0], 0.2, 1.5);
    random_sides(ps.side[1], 0.2, 1.5);
    dMatrix3 A, B, Z;
    for (int k = 0; k < 2; k++) {
        if (tilt > 0) random_tilt(A, rnd(0, tilt));
        else right_angles(A, 2, 0);
        if (turn == 1) {
            right_angles(Z, 2, (int)rnd(0, 4));
        } else if (turn == 2) {
            double z[3] = { 0, 0, 1 };
            rotation(Z, z, rnd(-M_PI, M_PI));
        } else {
            right_angles(Z, 2, 0);
        }
        mul(B, Z, A);
        memcpy(ps.R[k], B, sizeof B);
    }
    double x = rnd(-1, 1) * (double)ps.side[0][0] * 0.7;
    double y = rnd(-1, 1) * (double)ps.side[0][1] * 0.7;
    double h = 0.5 * (double)(ps.side[0][2] + ps.side[1][2]);
    double pen = rnd(-0.002, 0.01) * (double)ps.side[1][2];
    set_vec(ps.p[0], rnd(-5, 5), rnd(-5, 5), rnd(0, 5));
    set_vec(ps.p[1], ps.p[0][0] + x, ps.p[0][1] + y, ps.p[0][2] + h - pen);
    if (turn == 3) {   // equal boxes, a brick-wall offset: the pyramid's layers
        memcpy(ps.side[1], ps.side[0], sizeof(dVector3));
        ps.p[1][0] = ps.p[0][0] + (dReal)(rnd(0.45, 0.55) * (double)ps.side[0][0]);
        ps.p[1][1] = ps.p[0][1] + (dReal)rnd(-1e-3, 1e-3);
    }
    return check_pose(&ps, t, 1);
}

static int test_resting_stacks(void)
{
    tally t = { 0 };
    static const double tilts[] = { 0, 1e-9, 1e-6, 1e-4, 1e-3, 1e-2, 0.1 };
    for (int it = 0; it < 14000; it++) {
        double tilt = tilts[it % 7];
        if (resting_case(tilt, (it / 7) % 4, &t)) return 1;
    }
    printf("# resting: %d pairs, %d touching (%d face, %d edge), %d with over 4 points, %d "
           "culled\n", t.pairs, t.touching, t.face, t.edge, t.many, t.culled);
    CHECK(t.face > 10000 && t.culled > 100);
    return 0;
}

// Two boxes' edges crossed at random angles near a given one, and boxes
// deep in each other (centres close), where the clearance pass and the
// fallback point decide.
static int test_crossed_and_deep(void)
{
    tally t = { 0 };
    for (int it = 0; it < 6000; it++) {
        pose ps;
        random_sides(ps.side[0], 0.1, 1.5);
        random_sides(ps.side[1], 0.1, 1.5);
        if (it % 2 == 0) {   // an edge of box 1 across the top edge of box 0
            double ux[3] = { 1, 0, 0 }, uz[3] = { 0, 0, 1 };
            dMatrix3 A, B, C;
            rotation(A, ux, M_PI / 4 + rnd(-0.05, 0.05));
            right_angles(ps.R[0], 2, 0);
            rotation(B, uz, rnd(-M_PI, M_PI));
            mul(C, B, A);
            memcpy(ps.R[1], C, sizeof C);
            double lift = 0.5 * (double)ps.side[0][2] +
                          0.5 * sqrt((double)(ps.side[1][1] * ps.side[1][1] +
                                              ps.side[1][2] * ps.side[1][2])) * rnd(0.8, 1.01);
            set_vec(ps.p[0], 0, 0, 0);
            set_vec(ps.p[1], rnd(-0.5, 0.5) * (double)ps.side[0][0],
                    rnd(-0.5, 0.5) * (double)ps.side[0][1], lift);
        } else {   // deep
            random_rotation(ps.R[0]);
            random_rotation(ps.R[1]);
            set_vec(ps.p[0], 1, 2, 3);
            set_vec(ps.p[1], 1 + rnd(-0.1, 0.1), 2 + rnd(-0.1, 0.1), 3 + rnd(-0.1, 0.1));
        }
        if (check_pose(&ps, &t, it % 4 == 0)) return 1;
    }
    printf("# crossed and deep: %d pairs, %d touching (%d face, %d edge)\n", t.pairs, t.touching,
           t.face, t.edge);
    CHECK(t.edge > 500 && t.face > 500);
    return 0;
}

// dBoxBox takes any matrices and sides: skewed and scaled matrices (some
// with entries past the shortcuts' 1.25) and negative sides must give what
// the plain collider gives, whatever that means.
static int test_any_matrix(void)
{
    tally t = { 0 };
    for (int it = 0; it < 4000; it++) {
        pose ps;
        for (int k = 0; k < 2; k++) {
            random_sides(ps.side[k], it % 5 == 0 ? -0.3 : 0.1, 1.5);
            double spread = it % 3 == 0 ? 2.5 : 1.1;
            for (int i = 0; i < 12; i++)
                ps.R[k][i] = (dReal)(i % 4 == 3 ? 0 : rnd(-spread, spread));
        }
        set_vec(ps.p[0], 0, 0, 0);
        set_vec(ps.p[1], rnd(-1, 1), rnd(-1, 1), rnd(-1, 1));
        if (check_dboxbox(&ps, 0, &t) || check_dboxbox(&ps, 1, &t)) return 1;
    }
    printf("# any matrix: %d pairs, %d touching (%d face, %d edge)\n", t.pairs, t.touching, t.face,
           t.edge);
    CHECK(t.face > 500);
    return 0;
}

// dBoxBox's axis (its return code) for pose ps, box 0 against box 1.
static int axis_code(const pose *ps)
{
    dContactGeom c[8];
    dVector3 n;
    dReal depth;
    int code = 0;
    dBoxBox(ps->p[0], ps->R[0], ps->side[0], ps->p[1], ps->R[1], ps->side[1], n, &depth, &code, 8,
            c, sizeof(dContactGeom));
    return code;
}

// Box 1 of pose a moved to u of the way to its place in pose b (position
// and rotation entries blended: not a rotation in between, which dBoxBox
// takes as it comes, and the geoms clean).
static void blend(const pose *a, const pose *b, double u, pose *out)
{
    *out = *a;
    for (int i = 0; i < 3; i++)
        out->p[1][i] = (dReal)((1 - u) * (double)a->p[1][i] + u * (double)b->p[1][i]);
    for (int i = 0; i < 12; i++)
        out->R[1][i] = (dReal)((1 - u) * (double)a->R[1][i] + u * (double)b->R[1][i]);
}

// Near the ties: where the chosen axis changes along a path between two
// poses (one face axis to another, a face to an edge axis past the edge
// preference, touching to apart), found by bisection to the last bit of
// the path parameter; every pose of the bisection's last 24 steps (within
// 2^-30 of the change, many within rounding of it) is checked in both
// orders and through the geoms. Paths: box 1 slid or turned by tiny angles
// about the axes on a resting box, turned near 45 degrees across an edge,
// and between random poses.
static int test_near_ties(void)
{
    tally t = { 0 };
    int changes = 0, face_edge = 0, face_face = 0;
    for (int it = 0; it < 600; it++) {
        pose a, b;
        random_sides(a.side[0], 0.3, 1.5);
        random_sides(a.side[1], 0.3, 1.5);
        int kind = it % 3;
        if (kind == 0) {   // resting, turned by up to 1e-6 about an axis, slid
            double u[3] = { 0, 0, 0 };
            u[it / 3 % 3] = 1;
            right_angles(a.R[0], 2, 0);
            rotation(a.R[1], u, rnd(-1e-6, 1e-6));
            set_vec(a.p[0], 0, 0, 0);
            double h = 0.5 * (double)(a.side[0][2] + a.side[1][2]);
            set_vec(a.p[1], rnd(-0.3, 0.3), rnd(-0.3, 0.3), h - rnd(1e-4, 1e-2));
            b = a;
            rotation(b.R[1], u, rnd(-1e-6, 1e-6));
            set_vec(b.p[1], (double)a.p[1][0] + rnd(-0.5, 0.5) * (double)a.side[0][0],
                    (double)a.p[1][1], (double)a.p[1][2] + rnd(-0.02, 0.005));
        } else if (kind == 1) {   // an edge across an edge, turned about 45 degrees
            double ux[3] = { 1, 0, 0 }, uz[3] = { 0, 0, 1 };
            dMatrix3 A, B;
            right_angles(a.R[0], 2, 0);
            rotation(B, uz, rnd(-M_PI, M_PI));
            rotation(A, ux, M_PI / 4 + rnd(-0.3, 0.3));
            mul(a.R[1], B, A);
            set_vec(a.p[0], 0, 0, 0);
            double lift = 0.5 * (double)a.side[0][2] +
                          0.5 * sqrt((double)(a.side[1][1] * a.side[1][1] +
                                              a.side[1][2] * a.side[1][2])) * rnd(0.7, 0.95);
            set_vec(a.p[1], rnd(-0.6, 0.6) * (double)a.side[0][0],
                    rnd(-0.6, 0.6) * (double)a.side[0][1], lift);
            b = a;
            rotation(A, ux, M_PI / 4 + rnd(-0.3, 0.3));
            mul(b.R[1], B, A);
            set_vec(b.p[1], rnd(-0.6, 0.6) * (double)a.side[0][0],
                    rnd(-0.6, 0.6) * (double)a.side[0][1], lift * rnd(0.9, 1.2));
        } else {   // random poses in reach of each other
            random_rotation(a.R[0]);
            random_rotation(a.R[1]);
            set_vec(a.p[0], 0, 0, 0);
            set_vec(a.p[1], rnd(-0.8, 0.8), rnd(-0.8, 0.8), rnd(-0.8, 0.8));
            b = a;
            random_rotation(b.R[1]);
            set_vec(b.p[1], rnd(-0.8, 0.8), rnd(-0.8, 0.8), rnd(-0.8, 0.8));
        }
        int c0 = axis_code(&a), c1 = axis_code(&b);
        if (c0 == c1) continue;
        changes++;
        if ((c0 >= 7) != (c1 >= 7) && c0 > 0 && c1 > 0) face_edge++;
        if (c0 > 0 && c1 > 0 && c0 < 7 && c1 < 7) face_face++;
        double lo = 0, hi = 1;
        for (int step = 0; step < 54; step++) {
            double mid = 0.5 * (lo + hi);
            pose m;
            blend(&a, &b, mid, &m);
            if (axis_code(&m) == c0) lo = mid;
            else hi = mid;
            if (step >= 30 && check_pose(&m, &t, 1)) return 1;
        }
    }
    printf("# near ties: %d changes of axis (%d face to edge, %d face to face), %d pairs, %d "
           "touching (%d face, %d edge)\n", changes, face_edge, face_face, t.pairs, t.touching,
           t.face, t.edge);
    CHECK(face_edge > 30 && face_face > 30 && t.touching > 2000);
    return 0;
}

const test_case test_cases[] = {
    TEST_CASE(test_random_poses),
    TEST_CASE(test_resting_stacks),
    TEST_CASE(test_crossed_and_deep),
    TEST_CASE(test_any_matrix),
    TEST_CASE(test_near_ties),
    TEST_END,
};
