// SPDX-License-Identifier: BSD-3-Clause
//
// soak.c -- the long run: `soak steps=1000000 bodies=48 every=100000`. Steps
// the churning scene of soak_scene.h and prints, every `every` steps, the
// resident memory (VmRSS), the peak so far (VmHWM) and the mean step time of
// the last chunk; then one bench result line. Memory should stay flat and
// the step time should not drift.

#include "bench_common.h"
#include "soak_scene.h"

// Current resident memory in kB (VmRSS), -1 if unknown.
static long rss_kb(void)
{
    FILE *f = fopen("/proc/self/status", "r");
    char line[256];
    long kb = -1;
    while (f && kb < 0 && fgets(line, sizeof line, f))
        if (strncmp(line, "VmRSS:", 6) == 0) kb = strtol(line + 6, NULL, 10);
    if (f) fclose(f);
    return kb;
}

int main(int argc, char **argv)
{
    bench_args a = bench_args_init(argc, argv);
    long steps = bench_arg_int(&a, "steps", 1000000);
    long every = bench_arg_int(&a, "every", 100000);
    int bodies = (int)bench_arg_int(&a, "bodies", 48);
    bench_args_check(&a, "[steps=N] [every=N] [bodies=N]");

    dInitODE2(0);
    soak_scene *s = soak_create(bodies, 16);
    if (!s) return 1;
    printf("# steps  rss_kb  peak_kb  ms/step(chunk)  bodies_made  joints_made  geoms_made\n");
    double total = 0, chunk_start = bench_now();
    long min_rss = -1, max_rss = 0;
    int finite = 1;
    for (long i = 1; i <= steps; i++) {
        soak_step(s);
        if (i % every == 0 || i == steps) {
            double t = bench_now() - chunk_start;
            long n = i % every ? i % every : every;
            total += t;
            finite &= soak_all_finite(s);
            long rss = rss_kb();
            if (min_rss < 0 || rss < min_rss) min_rss = rss;
            if (rss > max_rss) max_rss = rss;
            soak_counts c = soak_count(s);
            printf("%8ld %7ld %8ld %10.4f %12ld %12ld %12ld\n", i, rss, bench_peak_rss_kb(),
                   1000.0 * t / (double)n, c.bodies_made, c.joints_made, c.geoms_made);
            fflush(stdout);
            chunk_start = bench_now();
        }
    }
    long final_rss = rss_kb();
    soak_counts c = soak_count(s);
    soak_destroy(s);
    dCloseODE();
    bench_report("soak", BENCH_ENGINE, "churn", bodies, (int)steps, 0, total,
                 "final_rss_kb=%ld min_rss_kb=%ld max_rss_kb=%ld finite=%d bodies_made=%ld "
                 "joints_made=%ld geoms_made=%ld", final_rss, min_rss, max_rss, finite,
                 c.bodies_made, c.joints_made, c.geoms_made);
    return finite ? 0 : 1;
}
