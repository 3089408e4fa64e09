// SPDX-License-Identifier: BSD-3-Clause
//
// bench_common.h -- what every bench scene shares, engine-neutral (C11 and C++): arguments,
// the monotonic clock, a seeded random generator and the key=value result line.
//
// Arguments are key=value words (`pyramid layers=40 steps=600 stepper=quick`); a scene reads
// the keys it knows with bench_arg_*() and rejects the others with bench_args_check(). The
// result is one line of key=value pairs on stdout, which bench/run parses.

#ifndef BENCH_COMMON_H
#define BENCH_COMMON_H

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <time.h>

#define BENCH_MAX_ARGS 16

// Instruction counting: under `valgrind --tool=callgrind --collect-atstart=no` (bench/run
// --instructions) only what lies between bench_count_on() and bench_count_off() is counted,
// the same timed parts as the clock's. Outside valgrind these are a few no-op instructions;
// without valgrind's headers, nothing.
#if defined(__has_include)
#if __has_include(<valgrind/callgrind.h>)
#include <valgrind/callgrind.h>
#define BENCH_HAVE_CALLGRIND 1
#endif
#endif
#ifdef BENCH_HAVE_CALLGRIND
#define bench_count_on() CALLGRIND_TOGGLE_COLLECT
#define bench_count_off() CALLGRIND_TOGGLE_COLLECT
#else
#define bench_count_on() ((void)0)
#define bench_count_off() ((void)0)
#endif

typedef struct bench_args {
    int argc;
    char **argv;
    int used[BENCH_MAX_ARGS];
} bench_args;

static inline bench_args bench_args_init(int argc, char **argv)
{
    bench_args a;
    memset(&a, 0, sizeof a);
    a.argc = argc < BENCH_MAX_ARGS ? argc : BENCH_MAX_ARGS;
    a.argv = argv;
    if (argc > BENCH_MAX_ARGS) {
        fprintf(stderr, "%s: too many arguments\n", argv[0]);
        exit(2);
    }
    return a;
}

// The value of key=value among the arguments, or NULL.
static inline const char *bench_arg_str(bench_args *a, const char *key, const char *def)
{
    size_t n = strlen(key);
    for (int i = 1; i < a->argc; i++) {
        if (strncmp(a->argv[i], key, n) == 0 && a->argv[i][n] == '=') {
            a->used[i] = 1;
            return a->argv[i] + n + 1;
        }
    }
    return def;
}

static inline long bench_arg_int(bench_args *a, const char *key, long def)
{
    const char *s = bench_arg_str(a, key, NULL);
    if (!s) return def;
    char *end;
    long v = strtol(s, &end, 10);
    if (*end || v <= 0) {
        fprintf(stderr, "%s: %s wants a positive integer, not '%s'\n", a->argv[0], key, s);
        exit(2);
    }
    return v;
}

// Exit with a usage message if an argument was not read by the scene.
static inline void bench_args_check(const bench_args *a, const char *usage)
{
    for (int i = 1; i < a->argc; i++) {
        if (!a->used[i]) {
            fprintf(stderr, "%s: unknown argument '%s'\nusage: %s %s\n", a->argv[0], a->argv[i],
                    a->argv[0], usage);
            exit(2);
        }
    }
}

static inline double bench_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

// xorshift64*: the same sequence in every engine's build of a scene.
typedef struct bench_rng {
    unsigned long long s;
} bench_rng;

static inline bench_rng bench_rng_init(unsigned long long seed)
{
    bench_rng r;
    r.s = seed * 0x9E3779B97F4A7C15ULL + 1;
    return r;
}

// Uniform in [lo, hi).
static inline double bench_rand(bench_rng *r, double lo, double hi)
{
    r->s ^= r->s >> 12;
    r->s ^= r->s << 25;
    r->s ^= r->s >> 27;
    unsigned long long x = r->s * 0x2545F4914F6CDD1DULL;
    return lo + (hi - lo) * (double)(x >> 11) * (1.0 / 9007199254740992.0);
}

// Peak resident memory of this program in kB: VmHWM from /proc (ru_maxrss would include the
// parent's peak, which Linux carries across exec), else ru_maxrss.
static inline long bench_peak_rss_kb(void)
{
    FILE *f = fopen("/proc/self/status", "r");
    char line[256];
    long kb = -1;
    while (f && kb < 0 && fgets(line, sizeof line, f))
        if (strncmp(line, "VmHWM:", 6) == 0) kb = strtol(line + 6, NULL, 10);
    if (f) fclose(f);
    if (kb < 0) {
        struct rusage ru;
        getrusage(RUSAGE_SELF, &ru);
        kb = ru.ru_maxrss;
    }
    return kb;
}

// The result line: scene, engine, timings and the peak resident memory of the process first,
// then the scene's own figures as "key=value" pairs given in fmt (printf format).
static inline void bench_report(const char *scene, const char *engine, const char *variant,
                                int size, int steps, double coll_s, double step_s,
                                const char *fmt, ...)
{
    printf("scene=%s engine=%s variant=%s size=%d steps=%d coll_s=%.6f step_s=%.6f "
           "ms_per_step=%.6f maxrss_kb=%ld ", scene, engine, variant, size, steps, coll_s,
           step_s, 1000.0 * (coll_s + step_s) / steps, bench_peak_rss_kb());
    va_list ap;
    va_start(ap, fmt);
    vprintf(fmt, ap);
    va_end(ap);
    printf("\n");
    fflush(stdout);
}

#endif
