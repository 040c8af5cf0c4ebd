/*
 * Every status code of the C API: each is produced by a call that should produce it, and has a
 * message of its own; on an error status nothing is written. Also the structure operations of
 * the IEC timers and the memory areas' STL operations, on short scenarios whose expected values
 * come from the manuals' rules (stated beside each check).
 *
 * Two codes cannot be produced from C, and are checked elsewhere or by argument:
 * - PLC_TIMERS_MISALIGNED_POINTER: forming a misaligned pointer is undefined behaviour in C
 *   (C11 6.3.2.3p7), so the Rust unit tests of bindings/c check it (src/lib.rs).
 * - PLC_TIMERS_INTERNAL_ERROR: no call path panics (see src/lib.rs); only its message is checked.
 * - PLC_TIMERS_LITERAL_INVALID: the library reports no error kind newer than this API; only its
 *   message is checked.
 */
#include "plc_timers.h"

#include <stdio.h>
#include <string.h>

static int checks, failures;

#define CHECK(cond)                                                                              \
    do {                                                                                         \
        checks++;                                                                                \
        if (!(cond)) {                                                                           \
            failures++;                                                                          \
            fprintf(stderr, "%s:%d: check failed: %s\n", __FILE__, __LINE__, #cond);             \
        }                                                                                        \
    } while (0)

/* The call returns `expected`. */
#define EXPECT(expected, call)                                                                   \
    do {                                                                                         \
        plc_timers_status got_ = (call);                                                         \
        checks++;                                                                                \
        if (got_ != (expected)) {                                                                \
            failures++;                                                                          \
            fprintf(stderr, "%s:%d: %s gave %d (%s), expected %s\n", __FILE__, __LINE__, #call,  \
                    (int)got_, plc_timers_status_message(got_), #expected);                      \
        }                                                                                        \
    } while (0)

static const struct {
    int code;
    const char *name;
} CODES[] = {
#define CODE(c) {c, #c}
    CODE(PLC_TIMERS_OK),
    CODE(PLC_TIMERS_NULL_POINTER),
    CODE(PLC_TIMERS_MISALIGNED_POINTER),
    CODE(PLC_TIMERS_INVALID_KIND),
    CODE(PLC_TIMERS_INVALID_STATE),
    CODE(PLC_TIMERS_INVALID_S5TIME),
    CODE(PLC_TIMERS_INVALID_PRESET),
    CODE(PLC_TIMERS_NO_SUCH_OPERAND),
    CODE(PLC_TIMERS_INVALID_TIME_BASE),
    CODE(PLC_TIMERS_INVALID_BCD_PRESET),
    CODE(PLC_TIMERS_LITERAL_EMPTY),
    CODE(PLC_TIMERS_LITERAL_PREFIX),
    CODE(PLC_TIMERS_LITERAL_NO_COMPONENTS),
    CODE(PLC_TIMERS_LITERAL_MISSING_UNIT),
    CODE(PLC_TIMERS_LITERAL_UNKNOWN_UNIT),
    CODE(PLC_TIMERS_LITERAL_MISSING_DIGITS),
    CODE(PLC_TIMERS_LITERAL_UNEXPECTED_CHAR),
    CODE(PLC_TIMERS_LITERAL_UNIT_ORDER),
    CODE(PLC_TIMERS_LITERAL_COMPONENT_RANGE),
    CODE(PLC_TIMERS_LITERAL_FRACTION),
    CODE(PLC_TIMERS_LITERAL_OVERFLOW),
    CODE(PLC_TIMERS_LITERAL_HEX_DIGITS),
    CODE(PLC_TIMERS_LITERAL_BCD_DIGIT),
    CODE(PLC_TIMERS_LITERAL_NEGATIVE),
    CODE(PLC_TIMERS_LITERAL_OUT_OF_RANGE),
    CODE(PLC_TIMERS_LITERAL_INVALID),
    CODE(PLC_TIMERS_PRESET_SYNTAX),
    CODE(PLC_TIMERS_PRESET_OUT_OF_RANGE),
    CODE(PLC_TIMERS_PRESET_BCD_DIGIT),
    CODE(PLC_TIMERS_INTERNAL_ERROR),
};
#define CODE_COUNT ((int)(sizeof CODES / sizeof CODES[0]))

/* Every code has a message of its own; any other code is unknown. */
static void messages(void) {
    const char *unknown = plc_timers_status_message(-1);
    CHECK(strcmp(unknown, "unknown status code") == 0);
    CHECK(strcmp(plc_timers_status_message(12345), "unknown status code") == 0);
    for (int i = 0; i < CODE_COUNT; i++) {
        const char *m = plc_timers_status_message(CODES[i].code);
        CHECK(m != NULL && m[0] != '\0');
        if (strcmp(m, unknown) == 0) {
            failures++;
            fprintf(stderr, "%s has no message\n", CODES[i].name);
        }
        for (int j = 0; j < i; j++)
            if (strcmp(m, plc_timers_status_message(CODES[j].code)) == 0) {
                failures++;
                fprintf(stderr, "%s and %s share a message\n", CODES[i].name, CODES[j].name);
            }
        checks++;
    }
}

/* A literal parse gives `status` at byte `position` and leaves the value untouched. */
static void s5time_error(const char *text, plc_timers_status status, size_t position) {
    uint16_t word = 0xBEEF;
    size_t at = 9999;
    plc_timers_status got = plc_timers_s5time_parse(text, &word, &at);
    checks++;
    if (got != status || at != position || word != 0xBEEF) {
        failures++;
        fprintf(stderr, "s5time_parse(\"%s\"): status %d at %zu (word %04X), expected %d at %zu\n",
                text, (int)got, at, word, (int)status, position);
    }
}

static void time_error(const char *text, plc_timers_status status, size_t position) {
    int32_t ms = 4242;
    size_t at = 9999;
    plc_timers_status got = plc_timers_time_parse(text, &ms, &at);
    checks++;
    if (got != status || at != position || ms != 4242) {
        failures++;
        fprintf(stderr, "time_parse(\"%s\"): status %d at %zu (ms %d), expected %d at %zu\n", text,
                (int)got, at, ms, (int)status, position);
    }
}

static void ltime_error(const char *text, plc_timers_status status, size_t position) {
    int64_t ns = 4242;
    size_t at = 9999;
    plc_timers_status got = plc_timers_ltime_parse(text, &ns, &at);
    checks++;
    if (got != status || at != position || ns != 4242) {
        failures++;
        fprintf(stderr,
                "ltime_parse(\"%s\"): status %d at %zu (ns %lld), expected %d at %zu\n", text,
                (int)got, at, (long long)ns, (int)status, position);
    }
}

/* The LTIME literals (LTIME-LIT-01): the units D H M S MS US NS, the full signed 64-bit range of
 * nanoseconds, and each error with its position, as for TIME. */
static void ltime_parser(void) {
    int64_t ns = 0;
    size_t at = 0;
    EXPECT(PLC_TIMERS_OK, plc_timers_ltime_parse("LT#1MS500US", &ns, &at));
    CHECK(ns == 1500000);
    EXPECT(PLC_TIMERS_OK, plc_timers_ltime_parse("ltime#30d", &ns, NULL));
    CHECK(ns == INT64_C(30) * 86400 * 1000000000);
    EXPECT(PLC_TIMERS_OK, plc_timers_ltime_parse("LT#1D_2H_3M_4S_5MS_6US_7NS", &ns, NULL));
    CHECK(ns == ((((INT64_C(1) * 24 + 2) * 60 + 3) * 60 + 4) * 1000000000 + 5006007));
    EXPECT(PLC_TIMERS_OK,
           plc_timers_ltime_parse("LT#-106751D_23H_47M_16S_854MS_775US_808NS", &ns, NULL));
    CHECK(ns == INT64_MIN);
    EXPECT(PLC_TIMERS_OK,
           plc_timers_ltime_parse("LT#106751D_23H_47M_16S_854MS_775US_807NS", &ns, NULL));
    CHECK(ns == INT64_MAX);
    ltime_error("", PLC_TIMERS_LITERAL_EMPTY, 0);
    ltime_error("T#5S", PLC_TIMERS_LITERAL_PREFIX, 0); /* a TIME literal is not an LTIME one */
    ltime_error("LT#5X", PLC_TIMERS_LITERAL_UNKNOWN_UNIT, 4);
    ltime_error("LT#5US_75MS", PLC_TIMERS_LITERAL_UNIT_ORDER, 9);
    ltime_error("LT#1MS_1000US", PLC_TIMERS_LITERAL_COMPONENT_RANGE, 7);
    ltime_error("LT#5S\xff", PLC_TIMERS_LITERAL_UNEXPECTED_CHAR, 5); /* not UTF-8 */
    ltime_error("LT#106751D_23H_47M_16S_854MS_775US_808NS", PLC_TIMERS_LITERAL_OUT_OF_RANGE, 3);
    EXPECT(PLC_TIMERS_NULL_POINTER, plc_timers_ltime_parse(NULL, &ns, NULL));
    EXPECT(PLC_TIMERS_NULL_POINTER, plc_timers_ltime_parse("LT#1S", NULL, NULL));
}

static void parsers(void) {
    uint16_t word = 0;
    int32_t ms = 0;
    uint16_t count = 0;
    size_t at = 0;
    /* Values: the words and durations the manuals give (S5T#2M7S is 127 units of 1 s: base 2). */
    EXPECT(PLC_TIMERS_OK, plc_timers_s5time_parse("S5T#2M7S", &word, &at));
    CHECK(word == 0x2127);
    EXPECT(PLC_TIMERS_OK, plc_timers_s5time_parse("w#16#1050", &word, NULL));
    CHECK(word == 0x1050);
    EXPECT(PLC_TIMERS_OK, plc_timers_time_parse("T#2s_200ms", &ms, &at));
    CHECK(ms == 2200);
    EXPECT(PLC_TIMERS_OK, plc_timers_time_parse("T#-24D_20H_31M_23S_648MS", &ms, NULL));
    CHECK(ms == INT32_MIN);
    EXPECT(PLC_TIMERS_OK, plc_timers_counter_preset_parse("C#120", &count));
    CHECK(count == 120);
    EXPECT(PLC_TIMERS_OK, plc_timers_counter_preset_parse("W#16#0999", &count));
    CHECK(count == 999);

    /* Every literal error code, with the byte where the problem is. */
    time_error("", PLC_TIMERS_LITERAL_EMPTY, 0);
    time_error("X#5S", PLC_TIMERS_LITERAL_PREFIX, 0);
    time_error("T#", PLC_TIMERS_LITERAL_NO_COMPONENTS, 2);
    time_error("T#5", PLC_TIMERS_LITERAL_MISSING_UNIT, 3);
    time_error("T#5X", PLC_TIMERS_LITERAL_UNKNOWN_UNIT, 3);
    time_error("T#S", PLC_TIMERS_LITERAL_MISSING_DIGITS, 2);
    time_error("T#5S!", PLC_TIMERS_LITERAL_UNEXPECTED_CHAR, 4);
    time_error("T#5S\xff", PLC_TIMERS_LITERAL_UNEXPECTED_CHAR, 4); /* not UTF-8 */
    time_error("T#5S_75M", PLC_TIMERS_LITERAL_UNIT_ORDER, 7);
    time_error("T#1H_75M", PLC_TIMERS_LITERAL_COMPONENT_RANGE, 5);
    time_error("T#1.5S", PLC_TIMERS_LITERAL_FRACTION, 3);
    time_error("T#99999999999999999999999MS", PLC_TIMERS_LITERAL_OVERFLOW, 2);
    time_error("T#24D_20H_31M_23S_648MS", PLC_TIMERS_LITERAL_OUT_OF_RANGE, 2); /* at the value */
    s5time_error("W#16#", PLC_TIMERS_LITERAL_HEX_DIGITS, 5);
    s5time_error("W#16#00A1", PLC_TIMERS_LITERAL_BCD_DIGIT, 7);
    s5time_error("S5T#-5S", PLC_TIMERS_LITERAL_NEGATIVE, 4);
    s5time_error("S5T#2H47M", PLC_TIMERS_LITERAL_OUT_OF_RANGE, 4);

    /* The counter preset's codes (no position), and the value untouched. */
    count = 77;
    EXPECT(PLC_TIMERS_PRESET_SYNTAX, plc_timers_counter_preset_parse("C#x", &count));
    EXPECT(PLC_TIMERS_PRESET_OUT_OF_RANGE, plc_timers_counter_preset_parse("C#1000", &count));
    EXPECT(PLC_TIMERS_PRESET_BCD_DIGIT, plc_timers_counter_preset_parse("W#16#00A0", &count));
    CHECK(count == 77);

    /* NULL pointers; error_position may be NULL. */
    EXPECT(PLC_TIMERS_NULL_POINTER, plc_timers_s5time_parse(NULL, &word, &at));
    EXPECT(PLC_TIMERS_NULL_POINTER, plc_timers_s5time_parse("S5T#1S", NULL, &at));
    EXPECT(PLC_TIMERS_NULL_POINTER, plc_timers_time_parse(NULL, &ms, NULL));
    EXPECT(PLC_TIMERS_NULL_POINTER, plc_timers_time_parse("T#1S", NULL, NULL));
    EXPECT(PLC_TIMERS_LITERAL_EMPTY, plc_timers_time_parse("", &ms, NULL));
    EXPECT(PLC_TIMERS_NULL_POINTER, plc_timers_counter_preset_parse(NULL, &count));
    EXPECT(PLC_TIMERS_NULL_POINTER, plc_timers_counter_preset_parse("C#1", NULL));
}

/* An error leaves the state and the output as they were: compares bytes before and after. The
 * state structs have no padding; an output struct has, so it is filled with a pattern (every
 * byte defined) before the calls that must not write it. */
#define UNCHANGED(before, after) CHECK(memcmp(&(before), &(after), sizeof(before)) == 0)
#define FILL(x) memset(&(x), 0x5A, sizeof(x))

static void s5_timers(void) {
    plc_timers_s5_timer_ref ref, ref0;
    plc_timers_s5_timer opt, opt0;
    plc_timers_s5_output out, out0;
    plc_timers_s5_input in = {.s = true, .tv = 0x0050}; /* S5T#500MS: 50 units of 10 ms */
    EXPECT(PLC_TIMERS_NULL_POINTER, plc_timers_s5_timer_ref_init(NULL));
    EXPECT(PLC_TIMERS_NULL_POINTER, plc_timers_s5_timer_init(NULL));
    EXPECT(PLC_TIMERS_OK, plc_timers_s5_timer_ref_init(&ref));
    EXPECT(PLC_TIMERS_OK, plc_timers_s5_timer_init(&opt));
    EXPECT(PLC_TIMERS_OK, plc_timers_s5_timer_ref_call(&ref, PLC_TIMERS_S_ODT, 0, in, &out));
    CHECK(!out.q && out.bi == 50);
    EXPECT(PLC_TIMERS_OK, plc_timers_s5_timer_call(&opt, PLC_TIMERS_S_ODT, 0, in, &out));
    CHECK(!out.q && out.bi == 50);
    ref0 = ref, opt0 = opt;
    FILL(out), FILL(out0);
    EXPECT(PLC_TIMERS_NULL_POINTER, plc_timers_s5_timer_ref_call(NULL, 2, 10, in, &out));
    EXPECT(PLC_TIMERS_NULL_POINTER, plc_timers_s5_timer_ref_call(&ref, 2, 10, in, NULL));
    EXPECT(PLC_TIMERS_NULL_POINTER, plc_timers_s5_timer_call(NULL, 2, 10, in, &out));
    EXPECT(PLC_TIMERS_NULL_POINTER, plc_timers_s5_timer_call(&opt, 2, 10, in, NULL));
    EXPECT(PLC_TIMERS_INVALID_KIND, plc_timers_s5_timer_ref_call(&ref, 5, 10, in, &out));
    EXPECT(PLC_TIMERS_INVALID_KIND, plc_timers_s5_timer_call(&opt, -1, 10, in, &out));
    plc_timers_s5_input bad_tv = {.s = true, .tv = 0x00A0};
    EXPECT(PLC_TIMERS_INVALID_S5TIME, plc_timers_s5_timer_ref_call(&ref, 2, 10, bad_tv, &out));
    EXPECT(PLC_TIMERS_INVALID_S5TIME, plc_timers_s5_timer_call(&opt, 2, 10, bad_tv, &out));
    UNCHANGED(ref, ref0);
    UNCHANGED(opt, opt0);
    UNCHANGED(out, out0);
    /* Corrupted states: a value above 999, a flag byte 2, a bit outside the word's fields. */
    plc_timers_s5_timer_ref bad_ref = ref;
    bad_ref.value = 1000;
    EXPECT(PLC_TIMERS_INVALID_STATE, plc_timers_s5_timer_ref_call(&bad_ref, 2, 10, in, &out));
    bad_ref = ref;
    bad_ref.q = 2;
    EXPECT(PLC_TIMERS_INVALID_STATE, plc_timers_s5_timer_ref_call(&bad_ref, 2, 10, in, &out));
    bad_ref = ref;
    bad_ref.base = 4;
    EXPECT(PLC_TIMERS_INVALID_STATE, plc_timers_s5_timer_ref_call(&bad_ref, 2, 10, in, &out));
    plc_timers_s5_timer bad_opt = opt;
    bad_opt.word |= 1u << 31;
    EXPECT(PLC_TIMERS_INVALID_STATE, plc_timers_s5_timer_call(&bad_opt, 2, 10, in, &out));
    UNCHANGED(out, out0);
    /* 50 ticks of 10 ms later the on-delay has run out with S = 1: Q = 1 (LAD manual 9.5). */
    EXPECT(PLC_TIMERS_OK, plc_timers_s5_timer_ref_call(&ref, PLC_TIMERS_S_ODT, 500, in, &out));
    CHECK(out.q && out.bi == 0);
    EXPECT(PLC_TIMERS_OK, plc_timers_s5_timer_call(&opt, PLC_TIMERS_S_ODT, 500, in, &out));
    CHECK(out.q && out.bi == 0);
}

static void iec_timers(void) {
    plc_timers_iec_timer_ref ref, ref0;
    plc_timers_iec_timer opt, opt0;
    plc_timers_iec_output out, out0;
    plc_timers_iec_input on = {.in = true, .pt = 1000};
    CHECK(sizeof(plc_timers_iec_timer) == 16); /* the S7-1200 IEC_TIMER */
    CHECK(sizeof(plc_timers_iec_timer_ref) == 16);
    EXPECT(PLC_TIMERS_NULL_POINTER, plc_timers_iec_timer_ref_init(NULL));
    EXPECT(PLC_TIMERS_NULL_POINTER, plc_timers_iec_timer_init(NULL));
    EXPECT(PLC_TIMERS_OK, plc_timers_iec_timer_ref_init(&ref));
    EXPECT(PLC_TIMERS_OK, plc_timers_iec_timer_init(&opt));
    ref0 = ref, opt0 = opt;
    FILL(out), FILL(out0);
    EXPECT(PLC_TIMERS_NULL_POINTER, plc_timers_iec_timer_ref_call(NULL, 1, 0, on, &out));
    EXPECT(PLC_TIMERS_NULL_POINTER, plc_timers_iec_timer_ref_call(&ref, 1, 0, on, NULL));
    EXPECT(PLC_TIMERS_NULL_POINTER, plc_timers_iec_timer_call(NULL, 1, 0, on, &out));
    EXPECT(PLC_TIMERS_NULL_POINTER, plc_timers_iec_timer_call(&opt, 1, 0, on, NULL));
    EXPECT(PLC_TIMERS_INVALID_KIND, plc_timers_iec_timer_ref_call(&ref, 4, 0, on, &out));
    EXPECT(PLC_TIMERS_INVALID_KIND, plc_timers_iec_timer_call(&opt, -1, 0, on, &out));
    UNCHANGED(ref, ref0);
    UNCHANGED(opt, opt0);
    UNCHANGED(out, out0);
    plc_timers_iec_timer_ref bad_ref = ref;
    bad_ref.et = 5; /* ET above PT = 0 */
    EXPECT(PLC_TIMERS_INVALID_STATE, plc_timers_iec_timer_ref_call(&bad_ref, 1, 0, on, &out));
    bad_ref = ref;
    bad_ref.kind = 5;
    EXPECT(PLC_TIMERS_INVALID_STATE, plc_timers_iec_timer_ref_call(&bad_ref, 1, 0, on, &out));
    plc_timers_iec_timer bad_opt = opt;
    bad_opt.flags = 0x80; /* a flag bit no operation sets */
    EXPECT(PLC_TIMERS_INVALID_STATE, plc_timers_iec_timer_call(&bad_opt, 1, 0, on, &out));
    bad_opt = opt;
    bad_opt.reserved[1] = 1;
    EXPECT(PLC_TIMERS_INVALID_STATE, plc_timers_iec_timer_call(&bad_opt, 1, 0, on, &out));
    UNCHANGED(out, out0);

    /* The structure operations, on both forms alike. TON with PT = 1 s started at 0 ms. */
    EXPECT(PLC_TIMERS_OK, plc_timers_iec_timer_ref_call(&ref, PLC_TIMERS_TON, 0, on, &out));
    EXPECT(PLC_TIMERS_OK, plc_timers_iec_timer_call(&opt, PLC_TIMERS_TON, 0, on, &out));
    bool q[2];
    uint32_t et[2];
    /* Reading Q through the structure at 1000 ms updates it first: the time has run out
     * (S7-1200 manual, the self-resetting timer; IEC-ACCESS-01). */
    EXPECT(PLC_TIMERS_OK, plc_timers_iec_timer_ref_read_q(&ref, 1000, &q[0]));
    EXPECT(PLC_TIMERS_OK, plc_timers_iec_timer_read_q(&opt, 1000, &q[1]));
    CHECK(q[0] && q[1]);
    EXPECT(PLC_TIMERS_OK, plc_timers_iec_timer_ref_read_et(&ref, 1500, &et[0]));
    EXPECT(PLC_TIMERS_OK, plc_timers_iec_timer_read_et(&opt, 1500, &et[1]));
    CHECK(et[0] == 1000 && et[1] == 1000); /* ET stops at PT */
    EXPECT(PLC_TIMERS_NULL_POINTER, plc_timers_iec_timer_read_q(&opt, 0, NULL));
    EXPECT(PLC_TIMERS_NULL_POINTER, plc_timers_iec_timer_ref_read_et(NULL, 0, &et[0]));
    /* The RT coil clears ET and Q; the preset stays (IEC-RT-01). */
    EXPECT(PLC_TIMERS_OK, plc_timers_iec_timer_ref_reset(&ref));
    EXPECT(PLC_TIMERS_OK, plc_timers_iec_timer_reset(&opt));
    CHECK(ref.et == 0 && ref.q == 0 && ref.pt == 1000);
    CHECK(opt.et == 0 && (opt.flags & 2) == 0 && opt.pt == 1000);
    /* The PT coil loads the preset (IEC-PT-COIL-01). */
    EXPECT(PLC_TIMERS_OK, plc_timers_iec_timer_ref_preset(&ref, 250));
    EXPECT(PLC_TIMERS_OK, plc_timers_iec_timer_preset(&opt, 250));
    CHECK(ref.pt == 250 && opt.pt == 250);
    EXPECT(PLC_TIMERS_OK, plc_timers_iec_timer_preset(&opt, -7)); /* negative as 0 */
    CHECK(opt.pt == 0);
    /* RUN-STOP-RUN: retentive keeps the data, non-retentive returns to the initial structure
     * (IEC-RETAIN-01). */
    opt0 = opt;
    EXPECT(PLC_TIMERS_OK, plc_timers_iec_timer_run_stop_run(&opt, true));
    UNCHANGED(opt, opt0);
    EXPECT(PLC_TIMERS_OK, plc_timers_iec_timer_run_stop_run(&opt, false));
    EXPECT(PLC_TIMERS_OK, plc_timers_iec_timer_ref_run_stop_run(&ref, false));
    plc_timers_iec_timer zero_opt;
    plc_timers_iec_timer_ref zero_ref;
    memset(&zero_opt, 0, sizeof zero_opt);
    memset(&zero_ref, 0, sizeof zero_ref);
    UNCHANGED(opt, zero_opt);
    UNCHANGED(ref, zero_ref);
    EXPECT(PLC_TIMERS_NULL_POINTER, plc_timers_iec_timer_reset(NULL));
    EXPECT(PLC_TIMERS_NULL_POINTER, plc_timers_iec_timer_ref_preset(NULL, 1));
    EXPECT(PLC_TIMERS_NULL_POINTER, plc_timers_iec_timer_run_stop_run(NULL, false));
    bad_opt.flags = 0x80;
    EXPECT(PLC_TIMERS_INVALID_STATE, plc_timers_iec_timer_reset(&bad_opt));
}

static void counters(void) {
    plc_timers_counter_int_ref ref, ref0;
    plc_timers_counter_int opt, opt0;
    plc_timers_counter_int_output out, out0;
    plc_timers_counter_int_input up = {.cu = true, .pv = 1};
    /* No padding in the state structs: CV and two edge memories of the type, or CV and edges. */
    CHECK(sizeof(plc_timers_counter_lint_ref) == 24 && sizeof(plc_timers_counter_lint) == 16);
    CHECK(sizeof(plc_timers_counter_sint_ref) == 3 && sizeof(plc_timers_counter_sint) == 2);
    CHECK(sizeof(plc_timers_s5_timer) == 16 && sizeof(plc_timers_s5_timer_ref) == 16);
    CHECK(sizeof(plc_timers_s5_counter_ref) == 6 && sizeof(plc_timers_s5_counter) == 2);
    EXPECT(PLC_TIMERS_NULL_POINTER, plc_timers_counter_int_ref_init(NULL));
    EXPECT(PLC_TIMERS_NULL_POINTER, plc_timers_counter_ulint_init(NULL));
    EXPECT(PLC_TIMERS_OK, plc_timers_counter_int_ref_init(&ref));
    EXPECT(PLC_TIMERS_OK, plc_timers_counter_int_init(&opt));
    ref0 = ref, opt0 = opt;
    FILL(out), FILL(out0);
    EXPECT(PLC_TIMERS_NULL_POINTER, plc_timers_counter_int_ref_call(NULL, 0, up, &out));
    EXPECT(PLC_TIMERS_NULL_POINTER, plc_timers_counter_int_call(&opt, 0, up, NULL));
    EXPECT(PLC_TIMERS_INVALID_KIND, plc_timers_counter_int_ref_call(&ref, 3, up, &out));
    EXPECT(PLC_TIMERS_INVALID_KIND, plc_timers_counter_int_call(&opt, -1, up, &out));
    UNCHANGED(ref, ref0);
    UNCHANGED(opt, opt0);
    UNCHANGED(out, out0);
    ref.cd_prev = 2;
    EXPECT(PLC_TIMERS_INVALID_STATE, plc_timers_counter_int_ref_call(&ref, 0, up, &out));
    opt.edges = 4;
    EXPECT(PLC_TIMERS_INVALID_STATE, plc_timers_counter_int_call(&opt, 0, up, &out));
    ref = ref0, opt = opt0;
    /* CTU: a rising CU counts to 1 = PV: QU = 1. */
    EXPECT(PLC_TIMERS_OK, plc_timers_counter_int_ref_call(&ref, PLC_TIMERS_CTU, up, &out));
    CHECK(out.cv == 1 && out.qu && !out.qd);
    EXPECT(PLC_TIMERS_OK, plc_timers_counter_int_call(&opt, PLC_TIMERS_CTU, up, &out));
    CHECK(out.cv == 1 && out.qu && !out.qd);

    plc_timers_s5_counter_ref sref, sref0;
    plc_timers_s5_counter sopt, sopt0;
    plc_timers_s5_counter_output sout, sout0;
    plc_timers_s5_counter_input set = {.s = true, .pv = 5};
    EXPECT(PLC_TIMERS_NULL_POINTER, plc_timers_s5_counter_ref_init(NULL));
    EXPECT(PLC_TIMERS_NULL_POINTER, plc_timers_s5_counter_init(NULL));
    EXPECT(PLC_TIMERS_OK, plc_timers_s5_counter_ref_init(&sref));
    EXPECT(PLC_TIMERS_OK, plc_timers_s5_counter_init(&sopt));
    sref0 = sref, sopt0 = sopt;
    FILL(sout), FILL(sout0);
    EXPECT(PLC_TIMERS_NULL_POINTER, plc_timers_s5_counter_ref_call(&sref, 0, set, NULL));
    EXPECT(PLC_TIMERS_NULL_POINTER, plc_timers_s5_counter_call(NULL, 0, set, &sout));
    EXPECT(PLC_TIMERS_INVALID_KIND, plc_timers_s5_counter_ref_call(&sref, 3, set, &sout));
    EXPECT(PLC_TIMERS_INVALID_KIND, plc_timers_s5_counter_call(&sopt, 99, set, &sout));
    plc_timers_s5_counter_input bad_pv = {.s = true, .pv = 1000};
    EXPECT(PLC_TIMERS_INVALID_PRESET, plc_timers_s5_counter_ref_call(&sref, 0, bad_pv, &sout));
    EXPECT(PLC_TIMERS_INVALID_PRESET, plc_timers_s5_counter_call(&sopt, 0, bad_pv, &sout));
    UNCHANGED(sref, sref0);
    UNCHANGED(sopt, sopt0);
    UNCHANGED(sout, sout0);
    sref.cv = 1000;
    EXPECT(PLC_TIMERS_INVALID_STATE, plc_timers_s5_counter_ref_call(&sref, 0, set, &sout));
    sopt.word = 1000;
    EXPECT(PLC_TIMERS_INVALID_STATE, plc_timers_s5_counter_call(&sopt, 0, set, &sout));
    sref = sref0, sopt = sopt0;
    /* A rising S sets CV to PV = 5 (BCD 0x0005); Q = CV != 0. */
    EXPECT(PLC_TIMERS_OK, plc_timers_s5_counter_ref_call(&sref, PLC_TIMERS_S_CU, set, &sout));
    CHECK(sout.q && sout.cv == 5 && sout.cv_bcd == 0x0005);
    EXPECT(PLC_TIMERS_OK, plc_timers_s5_counter_call(&sopt, PLC_TIMERS_S_CU, set, &sout));
    CHECK(sout.q && sout.cv == 5 && sout.cv_bcd == 0x0005);

    /* The preset as the PLC holds C#123: the BCD word W#16#0123 is the count 123 (SC-BCD-01),
     * never 0x0123 = 291; a digit above 9 or bits 15-12 set is a status, nothing written. */
    plc_timers_s5_count count = 7;
    EXPECT(PLC_TIMERS_OK, plc_timers_s5_count_from_bcd(0x0123, &count));
    CHECK(count == 123);
    EXPECT(PLC_TIMERS_INVALID_BCD_PRESET, plc_timers_s5_count_from_bcd(0x012A, &count));
    EXPECT(PLC_TIMERS_INVALID_BCD_PRESET, plc_timers_s5_count_from_bcd(0x1000, &count));
    EXPECT(PLC_TIMERS_NULL_POINTER, plc_timers_s5_count_from_bcd(0x0123, NULL));
    CHECK(count == 123);
    plc_timers_s5_counter_input_bcd set_bcd = {.s = 1, .pv_bcd = 0x0123};
    plc_timers_s5_counter_input_bcd bad_bcd = {.s = 1, .pv_bcd = 0x00A0};
    sref = sref0, sopt = sopt0;
    FILL(sout), FILL(sout0);
    EXPECT(PLC_TIMERS_INVALID_BCD_PRESET,
           plc_timers_s5_counter_ref_call_bcd(&sref, PLC_TIMERS_S_CU, bad_bcd, &sout));
    EXPECT(PLC_TIMERS_INVALID_BCD_PRESET,
           plc_timers_s5_counter_call_bcd(&sopt, PLC_TIMERS_S_CU, bad_bcd, &sout));
    UNCHANGED(sref, sref0);
    UNCHANGED(sopt, sopt0);
    UNCHANGED(sout, sout0);
    EXPECT(PLC_TIMERS_OK, plc_timers_s5_counter_ref_call_bcd(&sref, PLC_TIMERS_S_CU, set_bcd, &sout));
    CHECK(sout.q && sout.cv == 123 && sout.cv_bcd == 0x0123);
    EXPECT(PLC_TIMERS_OK, plc_timers_s5_counter_call_bcd(&sopt, PLC_TIMERS_S_CU, set_bcd, &sout));
    CHECK(sout.q && sout.cv == 123 && sout.cv_bcd == 0x0123);
}

static plc_timers_timer_memory timers;
static plc_timers_counter_memory counter_area;

static void memory_areas(void) {
    uint16_t v = 0;
    bool q = false;
    CHECK(sizeof timers == 1032 && sizeof counter_area == 512);
    EXPECT(PLC_TIMERS_NULL_POINTER, plc_timers_timer_memory_init(NULL));
    EXPECT(PLC_TIMERS_OK, plc_timers_timer_memory_init(&timers));
    /* SE T 3 (S_PEXT) with S5T#1S = 100 units of 10 ms at 5000 ms; at 5300 ms 30 ticks of the
     * 10 ms base have passed: L T 3 gives 70, LC T 3 0x0070, A T 3 1 (a running pulse). */
    EXPECT(PLC_TIMERS_OK, plc_timers_timer_memory_advance_to(&timers, 5000));
    EXPECT(PLC_TIMERS_OK, plc_timers_timer_memory_start(&timers, 3, PLC_TIMERS_S_PEXT, true, 0x0100));
    EXPECT(PLC_TIMERS_OK, plc_timers_timer_memory_advance_to(&timers, 5300));
    EXPECT(PLC_TIMERS_OK, plc_timers_timer_memory_load(&timers, 3, &v));
    CHECK(v == 70);
    EXPECT(PLC_TIMERS_OK, plc_timers_timer_memory_load_bcd(&timers, 3, &v));
    CHECK(v == 0x0070);
    EXPECT(PLC_TIMERS_OK, plc_timers_timer_memory_status(&timers, 3, &q));
    CHECK(q);
    /* Five ticks of the 10 ms base by the runtime's own interrupt: 65 left. */
    EXPECT(PLC_TIMERS_OK, plc_timers_timer_memory_tick(&timers, PLC_TIMERS_BASE_10MS, 5));
    EXPECT(PLC_TIMERS_OK, plc_timers_timer_memory_load(&timers, 3, &v));
    CHECK(v == 65);
    /* R T 3 with RLO 1: stopped, value and status cleared; FR with RLO 1 is accepted. */
    EXPECT(PLC_TIMERS_OK, plc_timers_timer_memory_fr(&timers, 3, true));
    EXPECT(PLC_TIMERS_OK, plc_timers_timer_memory_reset(&timers, 3, true));
    EXPECT(PLC_TIMERS_OK, plc_timers_timer_memory_status(&timers, 3, &q));
    CHECK(!q);
    plc_timers_s5_output out;
    plc_timers_s5_input in = {.s = true, .tv = 0x0005};
    EXPECT(PLC_TIMERS_OK, plc_timers_timer_memory_call(&timers, 255, PLC_TIMERS_S_PULSE, 5300, in, &out));
    CHECK(out.q && out.bi == 5);
    /* Errors. */
    EXPECT(PLC_TIMERS_NO_SUCH_OPERAND, plc_timers_timer_memory_load(&timers, 256, &v));
    EXPECT(PLC_TIMERS_NO_SUCH_OPERAND, plc_timers_timer_memory_call(&timers, 256, 0, 0, in, &out));
    EXPECT(PLC_TIMERS_INVALID_TIME_BASE, plc_timers_timer_memory_tick(&timers, 4, 1));
    EXPECT(PLC_TIMERS_INVALID_KIND, plc_timers_timer_memory_start(&timers, 0, 7, true, 0x0100));
    EXPECT(PLC_TIMERS_INVALID_S5TIME, plc_timers_timer_memory_start(&timers, 0, 0, true, 0x00F0));
    EXPECT(PLC_TIMERS_NULL_POINTER, plc_timers_timer_memory_status(&timers, 0, NULL));
    EXPECT(PLC_TIMERS_NULL_POINTER, plc_timers_timer_memory_advance_to(NULL, 0));
    timers.words[100] = 1000; /* a value field above 999 */
    EXPECT(PLC_TIMERS_INVALID_STATE, plc_timers_timer_memory_load(&timers, 0, &v));

    EXPECT(PLC_TIMERS_NULL_POINTER, plc_timers_counter_memory_init(NULL));
    EXPECT(PLC_TIMERS_OK, plc_timers_counter_memory_init(&counter_area));
    /* S C 1 with 10, then five CD with the sensor 1,0,1,0,1 (three rising edges): 7 left;
     * CU C 0 likewise: 3. */
    EXPECT(PLC_TIMERS_OK, plc_timers_counter_memory_set(&counter_area, 1, true, 10));
    for (int i = 0; i < 5; i++) {
        EXPECT(PLC_TIMERS_OK, plc_timers_counter_memory_cd(&counter_area, 1, i % 2 == 0));
        EXPECT(PLC_TIMERS_OK, plc_timers_counter_memory_cu(&counter_area, 0, i % 2 == 0));
    }
    EXPECT(PLC_TIMERS_OK, plc_timers_counter_memory_load_bcd(&counter_area, 1, &v));
    CHECK(v == 0x0007);
    EXPECT(PLC_TIMERS_OK, plc_timers_counter_memory_load(&counter_area, 0, &v));
    CHECK(v == 3);
    EXPECT(PLC_TIMERS_OK, plc_timers_counter_memory_fr(&counter_area, 0, true));
    EXPECT(PLC_TIMERS_OK, plc_timers_counter_memory_reset(&counter_area, 0, true));
    EXPECT(PLC_TIMERS_OK, plc_timers_counter_memory_status(&counter_area, 0, &q));
    CHECK(!q);
    plc_timers_s5_counter_output sout;
    plc_timers_s5_counter_input up = {.cu = true};
    EXPECT(PLC_TIMERS_OK, plc_timers_counter_memory_call(&counter_area, 9, PLC_TIMERS_S_CU, up, &sout));
    CHECK(sout.q && sout.cv == 1);
    EXPECT(PLC_TIMERS_NO_SUCH_OPERAND, plc_timers_counter_memory_cu(&counter_area, 256, true));
    EXPECT(PLC_TIMERS_INVALID_PRESET, plc_timers_counter_memory_set(&counter_area, 0, true, 1000));
    EXPECT(PLC_TIMERS_INVALID_KIND, plc_timers_counter_memory_call(&counter_area, 0, 3, up, &sout));
    /* S C n after L C#123: ACCU 1 holds W#16#0123, the count 123. */
    EXPECT(PLC_TIMERS_OK, plc_timers_counter_memory_set_bcd(&counter_area, 4, 1, 0x0123));
    EXPECT(PLC_TIMERS_OK, plc_timers_counter_memory_load(&counter_area, 4, &v));
    CHECK(v == 123);
    EXPECT(PLC_TIMERS_INVALID_BCD_PRESET,
           plc_timers_counter_memory_set_bcd(&counter_area, 5, 1, 0x0F00));
    plc_timers_s5_counter_input_bcd set_bcd = {.s = 1, .pv_bcd = 0x0042};
    EXPECT(PLC_TIMERS_OK,
           plc_timers_counter_memory_call_bcd(&counter_area, 6, PLC_TIMERS_S_CU, set_bcd, &sout));
    CHECK(sout.cv == 42 && sout.cv_bcd == 0x0042);
    set_bcd.pv_bcd = 0x0999 + 1; /* 0x099A: a digit above 9 */
    EXPECT(PLC_TIMERS_INVALID_BCD_PRESET,
           plc_timers_counter_memory_call_bcd(&counter_area, 6, PLC_TIMERS_S_CU, set_bcd, &sout));
    EXPECT(PLC_TIMERS_NULL_POINTER, plc_timers_counter_memory_load(NULL, 0, &v));
    counter_area.words[7] = 0x03E8; /* CV 1000 */
    EXPECT(PLC_TIMERS_INVALID_STATE, plc_timers_counter_memory_status(&counter_area, 0, &q));
}

/* The same on LTIME (IEC_LTIMER, 32 bytes): TON with PT = 1 s = 10^9 ns started at 0 ns. */
static void iec_ltimers(void) {
    plc_timers_iec_ltimer_ref ref, ref0;
    plc_timers_iec_ltimer opt, opt0;
    plc_timers_iec_ltime_output out, out0;
    plc_timers_iec_ltime_input on = {.in = true, .pt_ns = 1000000000};
    CHECK(sizeof(plc_timers_iec_ltimer) == 32); /* the S7-1500 IEC_LTIMER */
    CHECK(sizeof(plc_timers_iec_ltimer_ref) == 32);
    EXPECT(PLC_TIMERS_NULL_POINTER, plc_timers_iec_ltimer_ref_init(NULL));
    EXPECT(PLC_TIMERS_NULL_POINTER, plc_timers_iec_ltimer_init(NULL));
    EXPECT(PLC_TIMERS_OK, plc_timers_iec_ltimer_ref_init(&ref));
    EXPECT(PLC_TIMERS_OK, plc_timers_iec_ltimer_init(&opt));
    ref0 = ref, opt0 = opt;
    FILL(out), FILL(out0);
    EXPECT(PLC_TIMERS_NULL_POINTER, plc_timers_iec_ltimer_ref_call(NULL, 1, 0, on, &out));
    EXPECT(PLC_TIMERS_NULL_POINTER, plc_timers_iec_ltimer_call(&opt, 1, 0, on, NULL));
    EXPECT(PLC_TIMERS_INVALID_KIND, plc_timers_iec_ltimer_ref_call(&ref, 4, 0, on, &out));
    EXPECT(PLC_TIMERS_INVALID_KIND, plc_timers_iec_ltimer_call(&opt, -1, 0, on, &out));
    UNCHANGED(ref, ref0);
    UNCHANGED(opt, opt0);
    UNCHANGED(out, out0);
    plc_timers_iec_ltimer_ref bad_ref = ref;
    bad_ref.et = 5; /* ET above PT = 0 */
    EXPECT(PLC_TIMERS_INVALID_STATE, plc_timers_iec_ltimer_ref_call(&bad_ref, 1, 0, on, &out));
    bad_ref = ref;
    bad_ref.reserved[3] = 1;
    EXPECT(PLC_TIMERS_INVALID_STATE, plc_timers_iec_ltimer_ref_call(&bad_ref, 1, 0, on, &out));
    plc_timers_iec_ltimer bad_opt = opt;
    bad_opt.flags = 0x80;
    EXPECT(PLC_TIMERS_INVALID_STATE, plc_timers_iec_ltimer_call(&bad_opt, 1, 0, on, &out));
    bad_opt = opt;
    bad_opt.reserved[6] = 1; /* the padding to 32 bytes */
    EXPECT(PLC_TIMERS_INVALID_STATE, plc_timers_iec_ltimer_call(&bad_opt, 1, 0, on, &out));
    UNCHANGED(out, out0);

    EXPECT(PLC_TIMERS_OK, plc_timers_iec_ltimer_ref_call(&ref, PLC_TIMERS_TON, 0, on, &out));
    EXPECT(PLC_TIMERS_OK, plc_timers_iec_ltimer_call(&opt, PLC_TIMERS_TON, 0, on, &out));
    bool q[2];
    uint64_t et[2];
    /* 1 ns short of PT: running; at PT the read finds the time run out (IEC-ACCESS-01). */
    EXPECT(PLC_TIMERS_OK, plc_timers_iec_ltimer_ref_read_q(&ref, 999999999, &q[0]));
    EXPECT(PLC_TIMERS_OK, plc_timers_iec_ltimer_read_q(&opt, 999999999, &q[1]));
    CHECK(!q[0] && !q[1]);
    EXPECT(PLC_TIMERS_OK, plc_timers_iec_ltimer_ref_read_q(&ref, 1000000000, &q[0]));
    EXPECT(PLC_TIMERS_OK, plc_timers_iec_ltimer_read_q(&opt, 1000000000, &q[1]));
    CHECK(q[0] && q[1]);
    EXPECT(PLC_TIMERS_OK, plc_timers_iec_ltimer_ref_read_et(&ref, 1500000000, &et[0]));
    EXPECT(PLC_TIMERS_OK, plc_timers_iec_ltimer_read_et(&opt, 1500000000, &et[1]));
    CHECK(et[0] == 1000000000 && et[1] == 1000000000); /* ET stops at PT */
    EXPECT(PLC_TIMERS_NULL_POINTER, plc_timers_iec_ltimer_read_q(&opt, 0, NULL));
    EXPECT(PLC_TIMERS_NULL_POINTER, plc_timers_iec_ltimer_ref_read_et(NULL, 0, &et[0]));
    /* The RT coil (IEC-RT-01), the PT coil (IEC-PT-COIL-01), negative PT as 0. */
    EXPECT(PLC_TIMERS_OK, plc_timers_iec_ltimer_ref_reset(&ref));
    EXPECT(PLC_TIMERS_OK, plc_timers_iec_ltimer_reset(&opt));
    CHECK(ref.et == 0 && ref.q == 0 && ref.pt == 1000000000);
    CHECK(opt.et == 0 && (opt.flags & 2) == 0 && opt.pt == 1000000000);
    /* A preset past TIME's range (LT#30D). */
    EXPECT(PLC_TIMERS_OK, plc_timers_iec_ltimer_ref_preset(&ref, INT64_C(2592000000000000)));
    EXPECT(PLC_TIMERS_OK, plc_timers_iec_ltimer_preset(&opt, INT64_C(2592000000000000)));
    CHECK(ref.pt == UINT64_C(2592000000000000) && opt.pt == UINT64_C(2592000000000000));
    EXPECT(PLC_TIMERS_OK, plc_timers_iec_ltimer_preset(&opt, INT64_MIN)); /* negative as 0 */
    CHECK(opt.pt == 0);
    /* RUN-STOP-RUN (IEC-RETAIN-01). */
    opt0 = opt;
    EXPECT(PLC_TIMERS_OK, plc_timers_iec_ltimer_run_stop_run(&opt, 7)); /* any byte but 0: TRUE */
    UNCHANGED(opt, opt0);
    EXPECT(PLC_TIMERS_OK, plc_timers_iec_ltimer_run_stop_run(&opt, false));
    EXPECT(PLC_TIMERS_OK, plc_timers_iec_ltimer_ref_run_stop_run(&ref, false));
    plc_timers_iec_ltimer zero_opt;
    plc_timers_iec_ltimer_ref zero_ref;
    memset(&zero_opt, 0, sizeof zero_opt);
    memset(&zero_ref, 0, sizeof zero_ref);
    UNCHANGED(opt, zero_opt);
    UNCHANGED(ref, zero_ref);
    EXPECT(PLC_TIMERS_NULL_POINTER, plc_timers_iec_ltimer_reset(NULL));
    EXPECT(PLC_TIMERS_NULL_POINTER, plc_timers_iec_ltimer_ref_preset(NULL, 1));
    EXPECT(PLC_TIMERS_NULL_POINTER, plc_timers_iec_ltimer_run_stop_run(NULL, false));
    bad_opt.flags = 0x80;
    EXPECT(PLC_TIMERS_INVALID_STATE, plc_timers_iec_ltimer_reset(&bad_opt));
}

int main(void) {
    messages();
    parsers();
    ltime_parser();
    s5_timers();
    iec_timers();
    iec_ltimers();
    counters();
    memory_areas();
    printf("%d status codes, %d checks, %d failed\n", CODE_COUNT, checks, failures);
    return failures ? 1 : 0;
}
