// SPDX-License-Identifier: BSD-3-Clause
//
// snapshot_format.c -- the header of world and space snapshots (snapshot.c,
// libodecollide's space_snapshot.c): a magic naming what the snapshot is of,
// the format version, the precision, the payload's size and checksum.
// Compiled into both libraries, as report.c is.

#include "snapshot_io.h"

#define SNAP_VERSION 2u   // 2: the warm-start cache as body-pair runs

static uint64_t fnv1a64(const unsigned char *p, size_t n)
{
    uint64_t h = 0xcbf29ce484222325u;
    for (size_t i = 0; i < n; i++) {
        h ^= p[i];
        h *= 0x100000001b3u;
    }
    return h;
}

void dxSnapWriteHeader(unsigned char *out, const char *magic, size_t payload_size)
{
    dxSnapWriter h = { out, 0, DX_SNAP_HEADER };
    dxSnapPut(&h, magic, 8);
    dxSnapPutU32(&h, SNAP_VERSION);
    dxSnapPutU32(&h, (uint32_t)sizeof(dReal));
    dxSnapPutU64(&h, payload_size);
    dxSnapPutU64(&h, fnv1a64(out + DX_SNAP_HEADER, payload_size));
}

const char *dxSnapCheckHeader(const unsigned char *p, size_t size, const char *magic,
                              const unsigned char **payload, size_t *n)
{
    if (size < DX_SNAP_HEADER) return "it is truncated (shorter than its header)";
    dxSnapReader h = { p, DX_SNAP_HEADER, 0, 0 };
    char m[8];
    dxSnapGet(&h, m, 8);
    if (memcmp(m, magic, 8) != 0) return "it is not a snapshot of this kind (bad magic)";
    if (dxSnapGetU32(&h) != SNAP_VERSION) return "its format version is not this library's";
    if (dxSnapGetU32(&h) != sizeof(dReal)) return "it was taken with another precision";
    const uint64_t len = dxSnapGetU64(&h), sum = dxSnapGetU64(&h);
    if (len > size - DX_SNAP_HEADER) return "it is truncated";
    if (len < size - DX_SNAP_HEADER) return "it has bytes after its end";
    if (fnv1a64(p + DX_SNAP_HEADER, (size_t)len) != sum)
        return "its checksum does not match (corrupted)";
    *payload = p + DX_SNAP_HEADER;
    *n = (size_t)len;
    return NULL;
}
