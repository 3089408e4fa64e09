// SPDX-License-Identifier: BSD-3-Clause
//
// test_error.c -- error, debug and message handlers, the allocation handlers,
// dInitODE/dCloseODE and the configuration string.

#include "test.h"

#include <string.h>

static int last_num;
static char last_text[256];
static int calls;

static void record(int num, const char *msg, va_list ap)
{
    last_num = num;
    vsnprintf(last_text, sizeof last_text, msg, ap);
    calls++;
}

static int test_message_handler_receives_formatted_text(void)
{
    calls = 0;
    dSetMessageHandler(record);

    dMessage(7, "value %d and %s", 42, "text");

    CHECK(dGetMessageHandler() == record);
    CHECK(calls == 1);
    CHECK(last_num == 7);
    CHECK(strcmp(last_text, "value 42 and text") == 0);
    dSetMessageHandler(0);
    CHECK(dGetMessageHandler() == 0);
    return 0;
}

static int test_handlers_are_independent(void)
{
    dSetErrorHandler(record);
    dSetDebugHandler(0);

    CHECK(dGetErrorHandler() == record);
    CHECK(dGetDebugHandler() == 0);
    CHECK(dGetMessageHandler() == 0);
    dSetErrorHandler(0);
    return 0;
}

static int test_bad_argument_names_function_and_argument(void)
{
    test_capture_reports();

    dInitODE2(0x80);   // unknown flag bits

    CHECK(test_captured_count() == 1);
    CHECK(test_captured_contains("dInitODE2"));
    CHECK(test_captured_contains("uiInitFlags"));
    return 0;
}

static int test_bad_argument_reaches_debug_handler_as_user_assert(void)
{
    calls = 0;
    dSetDebugHandler(record);

    int ok = dInitODE2(0x80);

    CHECK(ok == 0);
    CHECK(calls == 1);
    CHECK(last_num == d_ERR_UASSERT);
    dSetDebugHandler(0);
    return 0;
}

static size_t live_bytes;
static int allocs, frees;

static void *counting_alloc(dsizeint size)
{
    allocs++;
    live_bytes += size;
    return malloc(size);
}

static void *counting_realloc(void *p, dsizeint oldsize, dsizeint newsize)
{
    live_bytes += newsize - oldsize;
    return realloc(p, newsize);
}

static void counting_free(void *p, dsizeint size)
{
    frees++;
    live_bytes -= size;
    free(p);
}

static int test_allocation_goes_through_handlers(void)
{
    dSetAllocHandler(counting_alloc);
    dSetReallocHandler(counting_realloc);
    dSetFreeHandler(counting_free);
    allocs = frees = 0;
    live_bytes = 0;

    char *p = dAlloc(100);
    memset(p, 1, 100);
    p = dRealloc(p, 100, 300);
    memset(p, 2, 300);
    CHECK(live_bytes == 300);
    dFree(p, 300);

    CHECK(allocs == 1);
    CHECK(frees == 1);
    CHECK(live_bytes == 0);
    CHECK(dGetAllocHandler() == counting_alloc);
    CHECK(dGetReallocHandler() == counting_realloc);
    CHECK(dGetFreeHandler() == counting_free);
    dSetAllocHandler(0);
    dSetReallocHandler(0);
    dSetFreeHandler(0);
    return 0;
}

static int test_default_allocator_works_and_free_null_is_harmless(void)
{
    double *p = dAlloc(10 * sizeof *p);
    for (int i = 0; i < 10; i++) p[i] = i;
    p = dRealloc(p, 10 * sizeof *p, 20 * sizeof *p);

    CHECK(p[9] == 9);
    dFree(p, 20 * sizeof *p);
    dFree(NULL, 0);
    return 0;
}

static int test_init_and_close_nest(void)
{
    test_capture_reports();

    dInitODE();
    CHECK(dInitODE2(0) == 1);
    CHECK(dAllocateODEDataForThread(dAllocateMaskAll) == 1);
    dCleanupODEAllDataForThread();
    dCloseODE();
    dCloseODE();

    CHECK(test_captured_count() == 0);
    dCloseODE();   // one close too many is reported
    CHECK(test_captured_count() == 1);
    CHECK(test_captured_contains("dCloseODE"));
    return 0;
}

static int test_configuration_names_precision(void)
{
    CHECK(dCheckConfiguration("ODE"));
#ifdef dSINGLE
    CHECK(dCheckConfiguration("ODE_single_precision"));
    CHECK(!dCheckConfiguration("ODE_double_precision"));
#else
    CHECK(dCheckConfiguration("ODE_double_precision"));
    CHECK(!dCheckConfiguration("ODE_single_precision"));
#endif
    CHECK(!dCheckConfiguration("ODE_double"));   // tokens match whole
    CHECK(!dCheckConfiguration(""));
    CHECK(strncmp(dGetConfiguration(), "ODE", 3) == 0);
    return 0;
}

const test_case test_cases[] = {
    TEST_CASE(test_message_handler_receives_formatted_text),
    TEST_CASE(test_handlers_are_independent),
    TEST_CASE(test_bad_argument_names_function_and_argument),
    TEST_CASE(test_bad_argument_reaches_debug_handler_as_user_assert),
    TEST_CASE(test_allocation_goes_through_handlers),
    TEST_CASE(test_default_allocator_works_and_free_null_is_harmless),
    TEST_CASE(test_init_and_close_nest),
    TEST_CASE(test_configuration_names_precision),
    TEST_END
};
