// SPDX-License-Identifier: BSD-3-Clause
//
// snapshot_io.h -- the byte writer and reader of world snapshots (snapshot.c),
// shared with the parts that save their own state (quickstep_warm.c).
//
// The writer counts bytes and copies them only while they fit, so one
// function both sizes and writes a snapshot. The reader never reads past its
// end: a short read gives zeros and marks the reader bad.

#ifndef DX_SNAPSHOT_IO_H
#define DX_SNAPSHOT_IO_H

#include <ode/common.h>
#include <stdint.h>
#include <string.h>

struct dxWorld;

typedef struct dxSnapWriter {
    unsigned char *p;   // NULL: count only
    size_t n, cap;
} dxSnapWriter;

typedef struct dxSnapReader {
    const unsigned char *p;
    size_t n, at;
    int bad;
} dxSnapReader;

static inline void dxSnapPut(dxSnapWriter *w, const void *x, size_t size)
{
    if (w->p && w->n + size <= w->cap) memcpy(w->p + w->n, x, size);
    w->n += size;
}
static inline void dxSnapPutU32(dxSnapWriter *w, uint32_t x) { dxSnapPut(w, &x, sizeof x); }
static inline void dxSnapPutU64(dxSnapWriter *w, uint64_t x) { dxSnapPut(w, &x, sizeof x); }
static inline void dxSnapPutReals(dxSnapWriter *w, const dReal *x, size_t n)
{
    dxSnapPut(w, x, n * sizeof *x);
}

static inline void dxSnapGet(dxSnapReader *r, void *x, size_t size)
{
    if (r->bad || size > r->n - r->at) {
        r->bad = 1;
        memset(x, 0, size);
        return;
    }
    memcpy(x, r->p + r->at, size);
    r->at += size;
}
static inline uint32_t dxSnapGetU32(dxSnapReader *r)
{
    uint32_t x;
    dxSnapGet(r, &x, sizeof x);
    return x;
}
static inline uint64_t dxSnapGetU64(dxSnapReader *r)
{
    uint64_t x;
    dxSnapGet(r, &x, sizeof x);
    return x;
}
static inline void dxSnapGetReals(dxSnapReader *r, dReal *x, size_t n)
{
    dxSnapGet(r, x, n * sizeof *x);
}
// Skip size bytes (a check pass reads without keeping).
static inline void dxSnapSkip(dxSnapReader *r, size_t size)
{
    if (r->bad || size > r->n - r->at) r->bad = 1;
    else r->at += size;
}

// The header of every snapshot (snapshot_format.c, compiled into both
// libraries): 8 bytes of magic (a name and its zero), the format version,
// sizeof(dReal), the payload's size and its FNV-1a 64 checksum.
#define DX_SNAP_HEADER 32u
// Write the header of the payload that follows it at out + DX_SNAP_HEADER.
void dxSnapWriteHeader(unsigned char *out, const char *magic, size_t payload_size);
// Check a snapshot of size bytes; on success *payload and *n are its
// payload. Returns NULL, or what is wrong (for a message).
const char *dxSnapCheckHeader(const unsigned char *p, size_t size, const char *magic,
                              const unsigned char **payload, size_t *n);

// dWorldQuickStep's contact-force cache (quickstep_warm.c): write it; read
// it back, changing the world only if apply (a first pass checks). Load
// returns 0 if the data is inconsistent.
void dxWarmCacheSave(const struct dxWorld *w, dxSnapWriter *out);
int dxWarmCacheLoad(struct dxWorld *w, dxSnapReader *in, int apply);

#endif
