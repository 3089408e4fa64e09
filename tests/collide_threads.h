// SPDX-License-Identifier: BSD-3-Clause
//
// collide_threads.h -- the check shared by the tests of colliders that keep
// per-thread memory (trimesh scratch, heightfield patches, the trimesh
// temporal-coherence cache): two threads collide one shared geom with their
// own geoms at their own poses, round after round, and must get, bit for
// bit, the contacts each pose gave single-threaded.

#ifndef TESTS_COLLIDE_THREADS_H
#define TESTS_COLLIDE_THREADS_H

#include <ode/ode.h>

enum { CT_KINDS = 6, CT_POSES = 60, CT_MAXC = 16 };

// One thread's share: its geoms (kinds of them) and poses (each geom is
// placed at pose p in turn), the contacts recorded single-threaded, and the
// mismatches its thread counted.
typedef struct ct_worker {
    dGeomID target;   // shared by both threads, always the first argument
    dGeomID geom[CT_KINDS];
    int kinds, poses, rounds;
    dReal pose[CT_POSES][3];
    dContactGeom expected[CT_POSES][CT_KINDS][CT_MAXC];
    int expected_n[CT_POSES][CT_KINDS];
    int mismatches;
} ct_worker;

// Whether n contacts are the same bit for bit (geoms and sides included).
int ct_same_contacts(const dContactGeom *a, const dContactGeom *b, int n);
// Records every pose's contacts single-threaded; touching[k] counts the poses
// at which geom k touches the target.
void ct_record(ct_worker *w, int touching[CT_KINDS]);
// Runs the two workers at once, each in its own thread (with ODE's
// per-thread data allocated and freed there); returns their mismatches.
int ct_run_pair(ct_worker *a, ct_worker *b);

#endif
