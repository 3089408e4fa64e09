// SPDX-License-Identifier: BSD-3-Clause
//
// snapshot.c -- dWorldSnapshot / dWorldRestore (ours, <ode/snapshot.h>): a
// world's state to bytes and back, into the same world.
//
// Layout: header (snapshot_format.c), then the payload: the random seed, the world's parameters
// and step counter, each body (handle, generation, then its state), each
// non-contact joint (handle, generation, type, bodies, then the bytes of its
// type-specific part: plain numbers and flags for every class but contacts,
// which are not saved), then QuickStep's contact-force cache. Bodies and
// joints are matched by handle and generation, in list order, so a restore
// finds exactly the objects it saved or refuses. A restore reads the payload
// twice: once to check everything against the world, once to write.

#include "objects_internal.h"
#include "snapshot_io.h"

#include <ode/memory.h>
#include <ode/misc.h>
#include <ode/snapshot.h>
#include <stdio.h>

#define SNAP_MAGIC "ODESNAP"   // with its terminating zero: 8 bytes

static void put_adis(dxSnapWriter *o, const dxAutoDisable *a)
{
    dxSnapPutReals(o, &a->linear_threshold, 1);
    dxSnapPutReals(o, &a->angular_threshold, 1);
    dxSnapPutU32(o, a->average_samples);
    dxSnapPutU32(o, (uint32_t)a->idle_steps);
    dxSnapPutReals(o, &a->idle_time, 1);
}

static void get_adis(dxSnapReader *r, dxAutoDisable *a)
{
    dxSnapGetReals(r, &a->linear_threshold, 1);
    dxSnapGetReals(r, &a->angular_threshold, 1);
    a->average_samples = dxSnapGetU32(r);
    a->idle_steps = (int)dxSnapGetU32(r);
    dxSnapGetReals(r, &a->idle_time, 1);
}

static void put_damping(dxSnapWriter *o, const dxDamping *d)
{
    const dReal x[5] = { d->linear_scale, d->angular_scale, d->linear_threshold,
                         d->angular_threshold, d->max_angular_speed };
    dxSnapPutReals(o, x, 5);
}

static void get_damping(dxSnapReader *r, dxDamping *d)
{
    dReal x[5];
    dxSnapGetReals(r, x, 5);
    d->linear_scale = x[0];
    d->angular_scale = x[1];
    d->linear_threshold = x[2];
    d->angular_threshold = x[3];
    d->max_angular_speed = x[4];
}

static int is_saved_joint(const dxJoint *j) { return j->cls->type != dJointTypeContact; }

static void put_body(dxSnapWriter *o, const struct dxBody *b)
{
    dxSnapPutU64(o, (uint64_t)(uintptr_t)b);
    dxSnapPutU32(o, b->hdr.generation);
    dxSnapPutU32(o, b->flags);
    dxSnapPutReals(o, &b->mass.mass, 1);
    dxSnapPutReals(o, b->mass.c, 4);
    dxSnapPutReals(o, b->mass.I, 12);
    dxSnapPutReals(o, &b->inv_mass, 1);
    dxSnapPutReals(o, b->inv_inertia, 12);
    dxSnapPutReals(o, b->pos, 4);
    dxSnapPutReals(o, b->q, 4);
    dxSnapPutReals(o, b->R, 12);
    dxSnapPutReals(o, b->lvel, 4);
    dxSnapPutReals(o, b->avel, 4);
    dxSnapPutReals(o, b->force, 4);
    dxSnapPutReals(o, b->torque, 4);
    dxSnapPutReals(o, b->finite_rot_axis, 4);
    dxSnapPutReals(o, b->gyro_torque, 4);
    dxSnapPutReals(o, &b->gyro_work, 1);
    dxSnapPutReals(o, &b->gyro_pending, 1);
    put_adis(o, &b->adis);
    dxSnapPutU32(o, (uint32_t)b->adis_idle_steps);
    dxSnapPutReals(o, &b->adis_idle_time, 1);
    dxSnapPutU32(o, b->adis_sample_next);
    dxSnapPutU32(o, b->adis_samples_taken);
    dxSnapPutU32(o, b->adis_samples_size);
    if (b->adis_samples_size) {
        dxSnapPutReals(o, b->adis_lvel_samples, b->adis_samples_size);
        dxSnapPutReals(o, b->adis_avel_samples, b->adis_samples_size);
    }
    dxSnapPutReals(o, &b->sf1_threshold, 1);
    dxSnapPutU32(o, (uint32_t)b->sf1_steps);
    dxSnapPutU32(o, (uint32_t)b->sf1_idle_steps);
    put_damping(o, &b->damping);
}

static void put_joint(dxSnapWriter *o, const dxJoint *j)
{
    dxSnapPutU64(o, (uint64_t)(uintptr_t)j);
    dxSnapPutU32(o, j->hdr.generation);
    dxSnapPutU32(o, (uint32_t)j->cls->type);
    dxSnapPutU32(o, j->flags);
    dxSnapPutU64(o, (uint64_t)(uintptr_t)dxJointBody(j, 0));
    dxSnapPutU64(o, (uint64_t)(uintptr_t)dxJointBody(j, 1));
    const size_t tail = j->cls->size - sizeof(dxJoint);
    dxSnapPutU64(o, tail);
    dxSnapPut(o, (const char *)j + sizeof(dxJoint), tail);
}

// The payload (without the header).
static void put_payload(dxSnapWriter *o, const struct dxWorld *w)
{
    dxSnapPutU64(o, dRandGetSeed());
    dxSnapPutReals(o, w->gravity, 4);
    dxSnapPutReals(o, &w->erp, 1);
    dxSnapPutReals(o, &w->cfm, 1);
    dxSnapPutU32(o, (uint32_t)w->qs_iterations);
    dxSnapPutReals(o, &w->qs_w, 1);
    dxSnapPutReals(o, &w->max_correcting_vel, 1);
    dxSnapPutReals(o, &w->contact_surface_layer, 1);
    put_adis(o, &w->adis);
    dxSnapPutU32(o, (uint32_t)w->adis_flag);
    dxSnapPutU32(o, (uint32_t)w->sf1_auto_enable_depth);
    put_damping(o, &w->damping);
    dxSnapPutU32(o, w->step_count);

    dxSnapPutU32(o, (uint32_t)w->num_bodies);
    for (const struct dxBody *b = w->bodies; b; b = b->next) put_body(o, b);
    uint32_t nj = 0;
    for (const dxJoint *j = w->joints; j; j = j->next) nj += is_saved_joint(j);
    dxSnapPutU32(o, nj);
    for (const dxJoint *j = w->joints; j; j = j->next)
        if (is_saved_joint(j)) put_joint(o, j);
    dxWarmCacheSave(w, o);
}

size_t dWorldSnapshot(dWorldID w, void *buffer, size_t capacity)
{
    DX_CHECK_ARG(dxWorldIsLive(w), return 0, "world is NULL or was destroyed");
    dxSnapWriter count = { NULL, 0, 0 };
    put_payload(&count, w);
    const size_t total = DX_SNAP_HEADER + count.n;
    if (!buffer || capacity < total) return total;

    unsigned char *out = buffer;
    dxSnapWriter o = { out + DX_SNAP_HEADER, 0, count.n };
    put_payload(&o, w);
    dxSnapWriteHeader(out, SNAP_MAGIC, count.n);
    return total;
}

// ---- restore ---------------------------------------------------------------

// Read one body's record; check it names b (and, if apply, write it).
// Returns NULL, or what is wrong.
static const char *get_body(dxSnapReader *r, struct dxBody *b, int apply)
{
    struct dxBody s;
    memset(&s, 0, sizeof s);
    const uint64_t handle = dxSnapGetU64(r);
    const uint32_t generation = dxSnapGetU32(r);
    if (r->bad) return "it is truncated";
    if (handle != (uint64_t)(uintptr_t)b || generation != b->hdr.generation)
        return "the world's bodies are not those of the snapshot";
    s.flags = dxSnapGetU32(r);
    dxSnapGetReals(r, &s.mass.mass, 1);
    dxSnapGetReals(r, s.mass.c, 4);
    dxSnapGetReals(r, s.mass.I, 12);
    dxSnapGetReals(r, &s.inv_mass, 1);
    dxSnapGetReals(r, s.inv_inertia, 12);
    dxSnapGetReals(r, s.pos, 4);
    dxSnapGetReals(r, s.q, 4);
    dxSnapGetReals(r, s.R, 12);
    dxSnapGetReals(r, s.lvel, 4);
    dxSnapGetReals(r, s.avel, 4);
    dxSnapGetReals(r, s.force, 4);
    dxSnapGetReals(r, s.torque, 4);
    dxSnapGetReals(r, s.finite_rot_axis, 4);
    dxSnapGetReals(r, s.gyro_torque, 4);
    dxSnapGetReals(r, &s.gyro_work, 1);
    dxSnapGetReals(r, &s.gyro_pending, 1);
    get_adis(r, &s.adis);
    s.adis_idle_steps = (int)dxSnapGetU32(r);
    dxSnapGetReals(r, &s.adis_idle_time, 1);
    s.adis_sample_next = dxSnapGetU32(r);
    s.adis_samples_taken = dxSnapGetU32(r);
    s.adis_samples_size = dxSnapGetU32(r);
    if (r->bad) return "it is truncated";
    if (s.adis_samples_size > (1u << 24) || s.adis_sample_next > s.adis_samples_size)
        return "a body's auto-disable samples are inconsistent";
    const size_t nsamples = s.adis_samples_size;
    const unsigned char *samples = r->p + r->at;
    dxSnapSkip(r, 2 * nsamples * sizeof(dReal));
    dxSnapGetReals(r, &s.sf1_threshold, 1);
    s.sf1_steps = (int)dxSnapGetU32(r);
    s.sf1_idle_steps = (int)dxSnapGetU32(r);
    get_damping(r, &s.damping);
    if (r->bad) return "it is truncated";
    if (!apply) return NULL;

    if (b->adis_samples_size != s.adis_samples_size) {
        if (b->adis_samples_size) {
            dFree(b->adis_lvel_samples, b->adis_samples_size * sizeof(dReal));
            dFree(b->adis_avel_samples, b->adis_samples_size * sizeof(dReal));
        }
        b->adis_lvel_samples = nsamples ? dAlloc(nsamples * sizeof(dReal)) : NULL;
        b->adis_avel_samples = nsamples ? dAlloc(nsamples * sizeof(dReal)) : NULL;
        b->adis_samples_size = s.adis_samples_size;
    }
    if (nsamples) {
        memcpy(b->adis_lvel_samples, samples, nsamples * sizeof(dReal));
        memcpy(b->adis_avel_samples, samples + nsamples * sizeof(dReal),
               nsamples * sizeof(dReal));
    }
    b->flags = s.flags;
    b->mass = s.mass;
    b->inv_mass = s.inv_mass;
    memcpy(b->inv_inertia, s.inv_inertia, sizeof s.inv_inertia);
    memcpy(b->pos, s.pos, sizeof s.pos);
    memcpy(b->q, s.q, sizeof s.q);
    memcpy(b->R, s.R, sizeof s.R);
    memcpy(b->lvel, s.lvel, sizeof s.lvel);
    memcpy(b->avel, s.avel, sizeof s.avel);
    memcpy(b->force, s.force, sizeof s.force);
    memcpy(b->torque, s.torque, sizeof s.torque);
    memcpy(b->finite_rot_axis, s.finite_rot_axis, sizeof s.finite_rot_axis);
    memcpy(b->gyro_torque, s.gyro_torque, sizeof s.gyro_torque);
    b->gyro_work = s.gyro_work;
    b->gyro_pending = s.gyro_pending;
    b->adis = s.adis;
    b->adis_idle_steps = s.adis_idle_steps;
    b->adis_idle_time = s.adis_idle_time;
    b->adis_sample_next = s.adis_sample_next;
    b->adis_samples_taken = s.adis_samples_taken;
    b->sf1_threshold = s.sf1_threshold;
    b->sf1_steps = s.sf1_steps;
    b->sf1_idle_steps = s.sf1_idle_steps;
    b->damping = s.damping;
    return NULL;
}

// The same for a joint. Only the disabled flag is state; the others follow
// from how the joint was made and attached, which must not have changed.
static const char *get_joint(dxSnapReader *r, dxJoint *j, int apply)
{
    const uint64_t handle = dxSnapGetU64(r);
    const uint32_t generation = dxSnapGetU32(r);
    const uint32_t type = dxSnapGetU32(r);
    const uint32_t flags = dxSnapGetU32(r);
    const uint64_t b0 = dxSnapGetU64(r), b1 = dxSnapGetU64(r);
    const uint64_t tail = dxSnapGetU64(r);
    if (r->bad) return "it is truncated";
    if (handle != (uint64_t)(uintptr_t)j || generation != j->hdr.generation ||
        type != (uint32_t)j->cls->type)
        return "the world's joints are not those of the snapshot";
    if (b0 != (uint64_t)(uintptr_t)dxJointBody(j, 0) ||
        b1 != (uint64_t)(uintptr_t)dxJointBody(j, 1) ||
        (flags & ~(uint32_t)DX_JOINT_DISABLED) != (j->flags & ~(unsigned)DX_JOINT_DISABLED))
        return "a joint was attached to other bodies since the snapshot";
    if (tail != j->cls->size - sizeof(dxJoint)) return "a joint's record has the wrong size";
    const unsigned char *data = r->p + r->at;
    dxSnapSkip(r, (size_t)tail);
    if (r->bad) return "it is truncated";
    if (!apply) return NULL;
    memcpy((char *)j + sizeof(dxJoint), data, (size_t)tail);
    j->flags = (j->flags & ~(unsigned)DX_JOINT_DISABLED) | (flags & DX_JOINT_DISABLED);
    return NULL;
}

// Read (and if apply, write) the whole payload. Returns NULL or what is wrong.
static const char *get_payload(dxSnapReader *r, struct dxWorld *w, int apply)
{
    const uint64_t seed = dxSnapGetU64(r);
    struct dxWorld s;
    memset(&s, 0, sizeof s);
    dxSnapGetReals(r, s.gravity, 4);
    dxSnapGetReals(r, &s.erp, 1);
    dxSnapGetReals(r, &s.cfm, 1);
    s.qs_iterations = (int)dxSnapGetU32(r);
    dxSnapGetReals(r, &s.qs_w, 1);
    dxSnapGetReals(r, &s.max_correcting_vel, 1);
    dxSnapGetReals(r, &s.contact_surface_layer, 1);
    get_adis(r, &s.adis);
    s.adis_flag = (int)dxSnapGetU32(r);
    s.sf1_auto_enable_depth = (int)dxSnapGetU32(r);
    get_damping(r, &s.damping);
    s.step_count = dxSnapGetU32(r);
    const uint32_t nb = dxSnapGetU32(r);
    if (r->bad) return "it is truncated";
    if (nb != (uint32_t)w->num_bodies) return "the world's bodies are not those of the snapshot";
    if (apply) {
        dRandSetSeed((unsigned long)seed);
        memcpy(w->gravity, s.gravity, sizeof s.gravity);
        w->erp = s.erp;
        w->cfm = s.cfm;
        w->qs_iterations = s.qs_iterations;
        w->qs_w = s.qs_w;
        w->max_correcting_vel = s.max_correcting_vel;
        w->contact_surface_layer = s.contact_surface_layer;
        w->adis = s.adis;
        w->adis_flag = s.adis_flag;
        w->sf1_auto_enable_depth = s.sf1_auto_enable_depth;
        w->damping = s.damping;
        w->step_count = s.step_count;
    }
    for (struct dxBody *b = w->bodies; b; b = b->next) {
        const char *e = get_body(r, b, apply);
        if (e) return e;
    }
    const uint32_t nj = dxSnapGetU32(r);
    uint32_t have = 0;
    for (const dxJoint *j = w->joints; j; j = j->next) have += is_saved_joint(j);
    if (r->bad) return "it is truncated";
    if (nj != have) return "the world's joints are not those of the snapshot";
    for (dxJoint *j = w->joints; j; j = j->next) {
        if (!is_saved_joint(j)) continue;
        const char *e = get_joint(r, j, apply);
        if (e) return e;
    }
    if (!dxWarmCacheLoad(w, r, apply))
        return r->bad ? "it is truncated" : "its contact-force cache is inconsistent";
    if (r->at != r->n) return "it has bytes after its end";
    return NULL;
}

int dWorldRestore(dWorldID w, const void *buffer, size_t size)
{
    DX_CHECK_ARG(dxWorldIsLive(w), return 0, "world is NULL or was destroyed");
    DX_CHECK_ARG(buffer != NULL, return 0, "buffer is NULL");
    const unsigned char *payload = NULL;
    size_t n = 0;
    const char *e = dxSnapCheckHeader(buffer, size, SNAP_MAGIC, &payload, &n);
    DX_CHECK_ARG(e == NULL, return 0, "bad snapshot: %s", e);
    dxSnapReader check = { payload, n, 0, 0 };
    e = get_payload(&check, w, 0);
    DX_CHECK_ARG(e == NULL, return 0, "bad snapshot: %s", e);
    dxSnapReader r = { payload, n, 0, 0 };
    get_payload(&r, w, 1);
    // The geoms follow their bodies.
    for (struct dxBody *b = w->bodies; b; b = b->next) dxBodyNotifyMoved(b);
    return 1;
}

int dWorldSnapshotToFile(dWorldID w, const char *path)
{
    DX_CHECK_ARG(dxWorldIsLive(w), return 0, "world is NULL or was destroyed");
    DX_CHECK_ARG(path != NULL, return 0, "path is NULL");
    const size_t size = dWorldSnapshot(w, NULL, 0);
    void *buffer = dAlloc(size);
    dWorldSnapshot(w, buffer, size);
    FILE *f = fopen(path, "wb");
    int ok = f != NULL && fwrite(buffer, 1, size, f) == size;
    if (f && fclose(f) != 0) ok = 0;
    dFree(buffer, size);
    DX_CHECK_ARG(ok, return 0, "cannot write '%s'", path);
    return 1;
}

int dWorldRestoreFromFile(dWorldID w, const char *path)
{
    DX_CHECK_ARG(dxWorldIsLive(w), return 0, "world is NULL or was destroyed");
    DX_CHECK_ARG(path != NULL, return 0, "path is NULL");
    FILE *f = fopen(path, "rb");
    DX_CHECK_ARG(f != NULL, return 0, "cannot open '%s'", path);
    long size = -1;
    if (fseek(f, 0, SEEK_END) == 0) size = ftell(f);
    if (size < 0 || fseek(f, 0, SEEK_SET) != 0) {
        fclose(f);
        DX_CHECK_ARG(0, return 0, "cannot read '%s'", path);
    }
    void *buffer = dAlloc(size > 0 ? (size_t)size : 1);
    const int ok = fread(buffer, 1, (size_t)size, f) == (size_t)size;
    fclose(f);
    int restored = 0;
    if (ok) restored = dWorldRestore(w, buffer, (size_t)size);
    dFree(buffer, size > 0 ? (size_t)size : 1);
    DX_CHECK_ARG(ok, return 0, "cannot read '%s'", path);
    return restored;
}
