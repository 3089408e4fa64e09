// SPDX-License-Identifier: BSD-3-Clause
//
// test_misc.c -- the random number generator and the matrix helpers of misc.h.

#include "test.h"

#include <limits.h>
#include <stdint.h>

// The generator's formula, written out here: x' = (1664525 x + 1013904223) mod 2^32.
static uint32_t lcg_next(uint32_t x) { return (uint32_t)(1664525u * x + 1013904223u); }

// dRandInt of a raw draw r, written from its definition as nested conditions: xor-fold the
// high bits down while n is small, keep the b low bits the last fold left (b = 32 if none),
// and scale: floor(low * n / 2^b).
static int fold_scale(uint32_t r, uint32_t n)
{
    int b = 32;
    if (n <= 0x10000u) {
        r ^= r >> 16;
        b = 16;
        if (n <= 0x100u) {
            r ^= r >> 8;
            b = 8;
            if (n <= 0x10u) {
                r ^= r >> 4;
                b = 4;
                if (n <= 4u) {
                    r ^= r >> 2;
                    b = 2;
                    if (n <= 2u) {
                        r ^= r >> 1;
                        b = 1;
                    }
                }
            }
        }
    }
    uint64_t low = b == 32 ? r : r % (1u << b);
    return (int)(low * n / ((uint64_t)1 << b));
}

static int test_rand_follows_the_lcg_from_seed_zero(void)
{
    dRandSetSeed(0);
    CHECK(dRand() == 1013904223ul);   // 1664525 * 0 + 1013904223
    CHECK(dRand() == 1196435762ul);   // (1664525 * 1013904223 + 1013904223) mod 2^32
    uint32_t x = 1196435762u;
    for (int i = 0; i < 1000; i++) {
        x = lcg_next(x);
        CHECK(dRand() == x);
    }
    CHECK(dRandGetSeed() == x);
    return 0;
}

static int test_seed_is_kept_to_32_bits(void)
{
    dRandSetSeed(123456789ul);
    CHECK(dRandGetSeed() == 123456789ul);
    CHECK(dRand() == lcg_next(123456789u));
#if ULONG_MAX > 0xffffffffUL
    dRandSetSeed(0x100000005ul);   // bit 32 is dropped
    CHECK(dRandGetSeed() == 5);
    CHECK(dRand() == lcg_next(5));
#endif
    return 0;
}

static int test_test_rand_passes_and_restores_seed(void)
{
    dRandSetSeed(777);
    CHECK(dTestRand() == 1);
    CHECK(dRandGetSeed() == 777);
    return 0;
}

static int test_rand_int_known_values(void)
{
    dRandSetSeed(0);
    // 0x3c6ef35f folded by 16, 8, 4, 2, 1 bits is 0x284b5d95: low bit 1, 1 * 2 / 2 = 1.
    CHECK(dRandInt(2) == 1);
    // 1196435762 = 0x47502932 folded by 16 bits is 0x47506e62: low 16 bits 28258,
    // 28258 * 1000 / 65536 = 431.2.
    CHECK(dRandInt(1000) == 431);
    // No folding above 65536: 3519870697 * 70000 / 2^32 = 57367.9.
    CHECK(dRandInt(70000) == 57367);
    // 0xaaf95334 folded by 16, 8, 4, 2 bits: low 2 bits 2, 2 * 3 / 4 = 1.5.
    CHECK(dRandInt(3) == 1);
    return 0;
}

static int test_rand_int_matches_its_definition(void)
{
    static const int ns[] = {1, 2, 3, 4, 5, 15, 16, 17, 255, 256, 257, 1000,
                             65535, 65536, 65537, 1000000, INT_MAX};
    for (size_t t = 0; t < sizeof ns / sizeof ns[0]; t++) {
        dRandSetSeed(99 + t);
        uint32_t x = 99 + (uint32_t)t;
        for (int i = 0; i < 200; i++) {
            x = lcg_next(x);
            CHECK(dRandInt(ns[t]) == fold_scale(x, (uint32_t)ns[t]));
        }
    }
    return 0;
}

static int test_rand_int_stays_in_range_and_covers_small_ranges(void)
{
    dRandSetSeed(42);
    for (int n = 1; n <= 20; n++) {
        int seen[20] = {0};
        for (int i = 0; i < 400; i++) {   // 400 draws: missing a value of 20 has odds ~1e-8
            int v = dRandInt(n);
            CHECK(v >= 0 && v < n);
            seen[v] = 1;
        }
        for (int v = 0; v < n; v++) CHECK(seen[v]);
    }
    for (int i = 0; i < 1000; i++) {
        int v = dRandInt(INT_MAX);
        CHECK(v >= 0);
    }
    return 0;
}

static int test_rand_real_is_the_draw_over_2_to_32_minus_1(void)
{
    dRandSetSeed(0);
    dRandReal();
    dRandReal();
    dRandReal();
    CHECK_NEAR(dRandReal(), 2868466484.0 / 4294967295.0, TOL(0, 6e-8));   // rounding to float
    double sum = 0;
    for (int i = 0; i < 10000; i++) {
        dReal v = dRandReal();
        CHECK(v >= 0 && v <= 1);
        sum += v;
    }
    CHECK_NEAR(sum / 10000, 0.5, 0.02);   // 10 standard deviations of the mean (0.0029)
    // Seeds found by solving 1664525 x + 1013904223 = 0 and = 2^32 - 1 (mod 2^32).
    dRandSetSeed(0x25d60fe5ul);
    CHECK(dRandReal() == 0);
    dRandSetSeed(0x26f5b720ul);
    CHECK(dRandReal() == 1);
    return 0;
}

static int test_random_vector_and_matrix_draw_in_order(void)
{
    dReal v[5], M[3 * 8], expect[15];
    dRandSetSeed(17);
    for (int i = 0; i < 15; i++) expect[i] = (dRandReal() * 2 - 1) * REAL(3.0);

    dRandSetSeed(17);
    dMakeRandomVector(v, 5, 3);
    for (int i = 0; i < 5; i++) CHECK(v[i] == expect[i]);   // same operations: exact

    dSetValue(M, 24, 9);
    dRandSetSeed(17);
    dMakeRandomMatrix(M, 3, 5, 3);   // skip dPAD(5) == 8
    for (int i = 0; i < 3; i++) {
        for (int j = 0; j < 5; j++) CHECK(M[i * 8 + j] == expect[i * 5 + j]);
        for (int j = 5; j < 8; j++) CHECK(M[i * 8 + j] == 0);
    }
    for (int i = 0; i < 15; i++) CHECK(fabs(expect[i]) <= 3);
    return 0;
}

static int test_clear_upper_triangle(void)
{
    dReal A[12];
    dSetValue(A, 12, 5);
    dClearUpperTriangle(A, 3);   // skip 4
    for (int i = 0; i < 3; i++) {
        for (int j = 0; j < 3; j++) CHECK(A[i * 4 + j] == (j > i ? 0 : 5));
        CHECK(A[i * 4 + 3] == 5);   // padding untouched
    }
    return 0;
}

static int test_max_difference_on_known_inputs(void)
{
    // 2 x 3 with skip 4; the padding differs wildly and must be ignored.
    const dReal A[8] = {1, 2, 3, 100, 4, 5, 6, 100};
    const dReal B[8] = {1, REAL(2.5), 3, -100, REAL(3.0), 5, REAL(6.25), -100};
    CHECK(dMaxDifference(A, B, 2, 3) == 1);
    CHECK(dMaxDifference(A, B, 1, 3) == REAL(0.5));
    CHECK(dMaxDifference(A, A, 2, 3) == 0);

    // 3 x 3 lower triangle: the upper difference of 50 is ignored.
    dReal C[12] = {1, 50, 50, 0, 2, 3, 50, 0, 4, 5, 6, 0};
    dReal D[12] = {1, 0, 0, 0, 2, 3, 0, 0, 4, REAL(5.75), 6, 0};
    CHECK(dMaxDifferenceLowerTriangle(C, D, 3) == REAL(0.75));
    CHECK(dMaxDifference(C, D, 3, 3) == 50);
    return 0;
}

static int test_max_difference_skips_nan_like_ode(void)
{
    const dReal A[4] = {1, 2, 3, 4}, B[4] = {1, NAN, 3, 6};
    CHECK(dMaxDifference(A, B, 1, 4) == 2);
    return 0;
}

static int test_print_matrix_writes_rows(void)
{
    const dReal A[8] = {1, 2, REAL(3.5), 99, -4, 5, 6, 99};
    FILE *f = tmpfile();
    CHECK(f != NULL);
    dPrintMatrix(A, 2, 3, "%g ", f);
    char text[64] = {0};
    rewind(f);
    size_t got = fread(text, 1, sizeof text - 1, f);
    fclose(f);
    CHECK(got == strlen("1 2 3.5 \n-4 5 6 \n"));
    CHECK(strcmp(text, "1 2 3.5 \n-4 5 6 \n") == 0);
    return 0;
}

static int test_bad_arguments_are_reported(void)
{
    test_capture_reports();
    unsigned long before = dRandGetSeed();

    CHECK(dRandInt(0) == 0);
    CHECK(test_captured_contains("dRandInt") && test_captured_contains("n must be positive"));
    CHECK(dRandInt(-3) == 0);
    CHECK(test_captured_contains("got -3"));
    CHECK(dRandGetSeed() == before);   // no draw was consumed
    dMakeRandomMatrix(NULL, 2, 2, 1);
    CHECK(test_captured_contains("dMakeRandomMatrix") && test_captured_contains("A is NULL"));
    dReal A[1] = {1};
    dPrintMatrix(A, 1, 1, NULL, stdout);
    CHECK(test_captured_contains("dPrintMatrix") && test_captured_contains("fmt"));
    CHECK(dMaxDifference(A, A, -1, 1) == 0);
    CHECK(test_captured_contains("dMaxDifference"));
    CHECK(test_captured_count() == 5);
    return 0;
}

const test_case test_cases[] = {
    TEST_CASE(test_rand_follows_the_lcg_from_seed_zero),
    TEST_CASE(test_seed_is_kept_to_32_bits),
    TEST_CASE(test_test_rand_passes_and_restores_seed),
    TEST_CASE(test_rand_int_known_values),
    TEST_CASE(test_rand_int_matches_its_definition),
    TEST_CASE(test_rand_int_stays_in_range_and_covers_small_ranges),
    TEST_CASE(test_rand_real_is_the_draw_over_2_to_32_minus_1),
    TEST_CASE(test_random_vector_and_matrix_draw_in_order),
    TEST_CASE(test_clear_upper_triangle),
    TEST_CASE(test_max_difference_on_known_inputs),
    TEST_CASE(test_max_difference_skips_nan_like_ode),
    TEST_CASE(test_print_matrix_writes_rows),
    TEST_CASE(test_bad_arguments_are_reported),
    TEST_END
};
