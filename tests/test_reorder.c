// SPDX-License-Identifier: BSD-3-Clause
//
// test_reorder.c -- QuickStep's reshuffle of an island's rows (quickstep.c:
// one pass, friction rows moved behind their normal rows as the shuffle
// places them, the random places made ahead, eight at a time with AVX2)
// against the plain form written here from its definition: a Fisher-Yates
// shuffle downwards whose k-th step swaps place k with the high half of
// hash(state += 0x9e3779b9) * (k + 1), then one pass upwards swapping each
// friction row found before its normal row with it. Made-up islands: rows
// of contacts of one to three rows, rows bound by no other row and friction
// rows whose normal row is elsewhere, row indices scattered as the rows of
// an island are among the system's, in build order and scrambled; three
// reshuffles a step, as in the solver, also with bases that wrap around.

#include "test.h"
#include "quickstep.h"

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#define NO_ROW (~0u)
#define MAX_ROWS 6000
#define MAX_INDEX (2 * MAX_ROWS)

static uint32_t plain_next(uint32_t *state)
{
    uint32_t x = (*state += 0x9e3779b9u);
    x ^= x >> 16;
    x *= 0x7feb352du;
    x ^= x >> 15;
    x *= 0x846ca68bu;
    return x ^ (x >> 16);
}

// The plain form: the shuffle, then the pass upwards. at: scratch by row.
static void plain_reshuffle(int *o, int n, uint32_t *state, const unsigned *normal, int *at)
{
    for (int k = n - 1; k > 0; k--) {
        const int j = (int)(((uint64_t)plain_next(state) * (uint64_t)(k + 1)) >> 32);
        const int t = o[k];
        o[k] = o[j];
        o[j] = t;
    }
    for (int k = 0; k < n; k++) at[o[k]] = k;
    for (int k = 0; k < n; k++) {
        if (normal[o[k]] == NO_ROW) continue;
        const int j = at[normal[o[k]]];
        if (j <= k) continue;
        const int t = o[k];
        o[k] = o[j];
        o[j] = t;
        at[o[k]] = k;
        at[o[j]] = j;
    }
}

static uint32_t lcg(uint32_t *s)
{
    *s = *s * 1664525u + 1013904223u;
    return *s >> 8;
}

static int order_a[MAX_ROWS], order_b[MAX_ROWS], scratch[MAX_INDEX];
static unsigned normal[MAX_INDEX], at_and_one[MAX_INDEX + 1];
static unsigned *const at = at_and_one + 1;   // dxQuickReshuffle writes at[-1]

// An island of n rows (n > 0): contacts of 1-3 rows, a row bound by no row
// about every fifth, a friction row whose normal row is not in the island
// now and then; row indices increasing with gaps (rows of the system that
// are not the island's); scrambled if asked.
static void make_island(int n, int scramble, uint32_t *seed)
{
    for (int i = 0; i < MAX_INDEX; i++) normal[i] = NO_ROW;
    int r = (int)(lcg(seed) % 5), k = 0;
    while (k < n) {
        const uint32_t kind = lcg(seed) % 10;
        const int rows = kind < 2 ? 1 : 1 + (int)(lcg(seed) % 3);
        const int first = r;
        for (int i = 0; i < rows && k < n; i++) {
            order_a[k++] = r;
            if (i > 0) normal[r] = (unsigned)first;
            r += 1 + (lcg(seed) % 4 == 0);
        }
        if (kind == 9 && k < n) {   // normal row elsewhere: bound by nothing here
            order_a[k++] = r;
            r += 2;
        }
    }
    for (int i = n - 1; scramble && i > 0; i--) {
        const int j = (int)(lcg(seed) % (uint32_t)(i + 1)), t = order_a[i];
        order_a[i] = order_a[j];
        order_a[j] = t;
    }
    memcpy(order_b, order_a, sizeof(int) * (size_t)n);
}

// Every friction row after its normal row, and a permutation of the rows.
static int check_rule(int n)
{
    static int where[MAX_INDEX];
    for (int i = 0; i < MAX_INDEX; i++) where[i] = -1;
    for (int k = 0; k < n; k++) {
        CHECK(order_a[k] >= 0 && order_a[k] < MAX_INDEX && where[order_a[k]] < 0);
        where[order_a[k]] = k;
    }
    for (int k = 0; k < n; k++) {
        const unsigned nr = normal[order_a[k]];
        CHECK(nr == NO_ROW || where[nr] < 0 || where[nr] < k);
    }
    return 0;
}

// Three reshuffles (base0, base0 + n, base0 + 2n) of islands of n rows,
// against the plain form: the same orders and generator states.
static int check_sizes(unsigned base_offset)
{
    static const int sizes[] = { 1, 2, 3, 7, 8, 9, 63, 64, 65, 255, 256, 257, 258, 1000, 4711,
                                 MAX_ROWS };
    uint32_t seed = 12345;
    for (int avx2 = 0; avx2 < 2; avx2++) {
        dxQuickShuffleAVX2 = avx2;
        for (size_t s = 0; s < sizeof sizes / sizeof sizes[0]; s++) {
            for (int scramble = 0; scramble < 2; scramble++) {
                const int n = sizes[s];
                make_island(n, scramble, &seed);
                for (int i = 0; i < MAX_INDEX; i++) at[i] = ~0u;
                uint32_t state_a = lcg(&seed) * 2654435761u, state_b = state_a;
                const unsigned base0 = base_offset ? base_offset - (unsigned)n : 0;
                for (int g = 0; g < 3; g++) {
                    dxQuickReshuffle(order_a, n, &state_a, base0 + (unsigned)g * (unsigned)n, normal,
                                     at);
                    plain_reshuffle(order_b, n, &state_b, normal, scratch);
                    if (memcmp(order_a, order_b, sizeof(int) * (size_t)n) != 0 ||
                        state_a != state_b)
                        test_fail(__FILE__, __LINE__, "n %d, scrambled %d, AVX2 %d: reshuffle %d "
                                  "differs from the plain form", n, scramble, avx2, g);
                    CHECK(memcmp(order_a, order_b, sizeof(int) * (size_t)n) == 0);
                    CHECK(state_a == state_b);
                    if (check_rule(n)) return 1;
                }
            }
        }
    }
    dxQuickShuffleAVX2 = 1;
    return 0;
}

static int test_reshuffle_is_the_plain_form(void)
{
    return check_sizes(0);
}

// The step's bases wrap around 2^32 (many iterations of big islands): the
// rows placed are still told from those of the last reshuffle.
static int test_reshuffle_bases_wrap(void)
{
    return check_sizes(0xffffffffu - (unsigned)MAX_ROWS / 2);
}

// No rows, one row: nothing to shuffle, the generator untouched.
static int test_reshuffle_tiny(void)
{
    uint32_t state = 77;
    dxQuickReshuffle(order_a, 0, &state, 0, normal, at);
    CHECK(state == 77);
    order_a[0] = 5;
    normal[5] = NO_ROW;
    at[5] = ~0u;
    dxQuickReshuffle(order_a, 1, &state, 0, normal, at);
    CHECK(state == 77 && order_a[0] == 5);
    return 0;
}

const test_case test_cases[] = {
    TEST_CASE(test_reshuffle_is_the_plain_form),
    TEST_CASE(test_reshuffle_bases_wrap),
    TEST_CASE(test_reshuffle_tiny),
    TEST_END,
};
