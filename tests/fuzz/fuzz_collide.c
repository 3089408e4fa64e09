// SPDX-License-Identifier: BSD-3-Clause
//
// fuzz_collide.c -- dCollide on two geoms of any classes made from the input
// (sizes, poses and flags, degenerate, huge and non-finite values included),
// under the backend the input picks. Checked: the contacts' count, finiteness,
// unit normals, non-negative depths and g1/g2; again with the pair swapped, and
// with a skip larger than a dContactGeom.

#include "fuzz_shapes.h"

#include <string.h>

#define MAX_CONTACTS 64

// Contacts into a buffer of `stride`-byte records; the bytes between records
// must stay untouched.
static void collide_checked(dGeomID a, dGeomID b, int flags, int stride)
{
    static unsigned char buf[MAX_CONTACTS * (sizeof(dContactGeom) + 16)];
    memset(buf, 0xa5, sizeof buf);
    int n = dCollide(a, b, flags, (dContactGeom *)(void *)buf, stride);
    fz_check_contacts(a, b, flags, (const dContactGeom *)(void *)buf, stride, n);
    if (stride > (int)sizeof(dContactGeom))
        for (int i = 0; i < (flags & 0xffff); i++)
            for (int k = (int)sizeof(dContactGeom); k < stride; k++)
                if (buf[i * stride + k] != 0xa5)
                    fz_fail("dCollide wrote between contacts (skip %d)", stride);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static int ready;
    if (!ready) {
        dInitODE2(0);
        fz_install_handlers();
        ready = 1;
    }
    fz_input in = {data, size, 0};
    const char *const *names = dCollisionListBackends();
    unsigned nb = 0;
    while (names[nb]) nb++;
    dCollisionSetBackend(names[fz_pick(&in, nb)]);

    fz_shapes store = {0};
    dGeomID a = fz_make_geom(&in, 0, &store);
    dGeomID b = fz_make_geom(&in, 0, &store);
    if (a && b && fz_pair_cheap(&store, a, b)) {
        int count = 1 + (int)fz_pick(&in, MAX_CONTACTS);
        int flags = count | (fz_u8(&in) < 32 ? CONTACTS_UNIMPORTANT : 0);
        int stride = (int)sizeof(dContactGeom) + (fz_u8(&in) & 1 ? 16 : 0);
        collide_checked(a, b, flags, stride);
        collide_checked(b, a, flags, stride);
        // move one and collide again (caches keyed on the pose must follow)
        fz_pose_geom(&in, a);
        if (fz_pair_cheap(&store, a, b)) collide_checked(a, b, flags, stride);
    }
    if (a) dGeomDestroy(a);
    if (b) dGeomDestroy(b);
    fz_shapes_free(&store);
    dCollisionSetBackend("native");
    return 0;
}
