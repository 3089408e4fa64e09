// SPDX-License-Identifier: BSD-3-Clause
//
// dx_clones.h -- building a hot function twice, for AVX2 and for the
// baseline, with the version picked when the library is loaded (GNU ifunc:
// x86-64, ELF, glibc): DX_AVX2_CLONES, defined only where that works. Used
// by QuickStep's sweeps, contact rows and warm-start match and by box-box.
//
// Including it also silences the ABI note on vector types wider than the
// baseline's registers: the users pass their fours only between inlined
// functions, never through a call, so the note does not apply.

#ifndef DX_CLONES_H
#define DX_CLONES_H

#if defined(__GNUC__) && defined(__x86_64__) && defined(__ELF__) && defined(__GLIBC__) && \
    defined(__has_attribute)
#if __has_attribute(target_clones)
#define DX_AVX2_CLONES __attribute__((target_clones("avx2", "default")))
#endif
#endif

// DX_AVX2_CLONES_EXTERN: the same for a function called from other files.
// Clang 14 gives the versions of such a function names that callers in
// other files do not link to, so under clang it is built once, baseline.
#if defined(DX_AVX2_CLONES) && !defined(__clang__)
#define DX_AVX2_CLONES_EXTERN DX_AVX2_CLONES
#else
#define DX_AVX2_CLONES_EXTERN
#endif

#if defined(__clang__)
#if __has_warning("-Wpsabi")
#pragma clang diagnostic ignored "-Wpsabi"
#endif
#elif defined(__GNUC__)
#pragma GCC diagnostic ignored "-Wpsabi"
#endif

#endif
