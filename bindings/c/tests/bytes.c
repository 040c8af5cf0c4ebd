/*
 * Input bits are bytes (issue 37): every input byte 0x00 to 0xFF, in every input field and flag
 * parameter of every block, acts as 0 when it is 0 and as 1 otherwise, and the instance stays
 * valid.
 *
 * Each block runs a scenario of STEPS calls; input field f is "on" at the steps of PATTERN[f]
 * (chosen so that every field rises and falls, alone and together with the others). In the run
 * under test the on-value of field `tested` is the byte b, every other on-value 1; in the
 * comparison run it is (b != 0), that is 0 or 1. The two runs must give the same statuses,
 * outputs and state bytes after every call (a trace of them is compared), every status must
 * be PLC_TIMERS_OK (the instance stays valid: a call after the scenario is part of it), and,
 * so that no block passes vacuously, each block has some field whose 0 and 1 runs differ.
 *
 * Also the backward clock (rule S5TMR-CLOCK-01) through the C API: an S_ODT of S5T#1S executed
 * at 0, 600, 100 and 600 ms runs out at 1000 ms in each S5 form (LAD manual 9.5: 100 ticks of
 * 10 ms), and a TON given a clock 1 ms behind its start reads it as the 32-bit clock's wrap
 * (on LTIME: 1 ns behind, the 64-bit clock's wrap).
 */
#include "plc_timers.h"

#include <stdio.h>
#include <string.h>

static int checks, failures;

#define CHECK(cond, ...)                                                                         \
    do {                                                                                         \
        checks++;                                                                                \
        if (!(cond)) {                                                                           \
            failures++;                                                                          \
            fprintf(stderr, "%s:%d: check failed: %s: ", __FILE__, __LINE__, #cond);             \
            fprintf(stderr, __VA_ARGS__);                                                        \
            fputc('\n', stderr);                                                                 \
        }                                                                                        \
    } while (0)

enum { STEPS = 10, MAX_FIELDS = 6, TRACE_MAX = 16384 };

/* Bit k: the field is on at step k. */
static const unsigned PATTERN[MAX_FIELDS] = {0x2B6, 0x0A4, 0x141, 0x39A, 0x0D1, 0x25C};

/* A scenario's record: statuses, outputs and state bytes after every call. */
struct trace {
    size_t len;
    int bad_status;
    unsigned char bytes[TRACE_MAX];
};

static void put(struct trace *t, const void *p, size_t n) {
    if (t->len + n > TRACE_MAX) {
        fprintf(stderr, "trace too long\n");
        t->bad_status = 1;
        return;
    }
    memcpy(t->bytes + t->len, p, n);
    t->len += n;
}

static void status(struct trace *t, plc_timers_status s) {
    int32_t v = (int32_t)s;
    if (s != PLC_TIMERS_OK)
        t->bad_status = 1;
    put(t, &v, sizeof v);
}

/* The byte field `field` takes at `step`. */
static uint8_t in(int field, int step, int tested, uint8_t on) {
    if (!((PATTERN[field] >> step) & 1u))
        return 0;
    return field == tested ? on : 1;
}

/* A block: `run` plays the scenario of kind `kind` with field `tested` on as `on`. */
typedef void (*scenario)(int kind, int tested, uint8_t on, struct trace *t);

struct block {
    const char *name;
    scenario run;
    int kinds, fields;
};

/* ---- S5 timers ---------------------------------------------------------------------------- */

#define S5_TIMER_SCENARIO(NAME, TYPE, CALL)                                                      \
    static void NAME(int kind, int tested, uint8_t on, struct trace *t) {                        \
        TYPE timer;                                                                              \
        memset(&timer, 0, sizeof timer);                                                         \
        for (int k = 0; k <= STEPS; k++) {                                                       \
            struct plc_timers_s5_input i;                                                        \
            struct plc_timers_s5_output o;                                                       \
            memset(&i, 0, sizeof i);                                                             \
            i.s = in(0, k % STEPS, tested, on);                                                  \
            i.r = in(1, k % STEPS, tested, on);                                                  \
            i.fr = in(2, k % STEPS, tested, on);                                                 \
            i.tv = 0x0003; /* S5T#30MS */                                                        \
            status(t, CALL(&timer, kind, (uint64_t)k * 20, i, &o));                              \
            put(t, &o.q, sizeof o.q);                                                            \
            put(t, &o.bi, sizeof o.bi);                                                          \
            put(t, &o.bcd, sizeof o.bcd);                                                        \
            put(t, &timer, sizeof timer);                                                        \
        }                                                                                        \
    }

S5_TIMER_SCENARIO(s5_timer_ref, struct plc_timers_s5_timer_ref, plc_timers_s5_timer_ref_call)
S5_TIMER_SCENARIO(s5_timer_opt, struct plc_timers_s5_timer, plc_timers_s5_timer_call)

static struct plc_timers_timer_memory timers;
static struct plc_timers_counter_memory counters;

static void timer_memory_call(int kind, int tested, uint8_t on, struct trace *t) {
    memset(&timers, 0, sizeof timers);
    for (int k = 0; k <= STEPS; k++) {
        struct plc_timers_s5_input i;
        struct plc_timers_s5_output o;
        memset(&i, 0, sizeof i);
        i.s = in(0, k % STEPS, tested, on);
        i.r = in(1, k % STEPS, tested, on);
        i.fr = in(2, k % STEPS, tested, on);
        i.tv = 0x0003;
        status(t, plc_timers_timer_memory_call(&timers, 7, kind, (uint64_t)k * 20, i, &o));
        put(t, &o.q, sizeof o.q);
        put(t, &o.bi, sizeof o.bi);
        put(t, &o.bcd, sizeof o.bcd);
        put(t, &timers, sizeof timers);
    }
}

/* The STL operations' RLO parameters: FR, the start operation, R. */
static void timer_memory_stl(int kind, int tested, uint8_t on, struct trace *t) {
    memset(&timers, 0, sizeof timers);
    for (int k = 0; k <= STEPS; k++) {
        bool q;
        uint16_t bi;
        status(t, plc_timers_timer_memory_advance_to(&timers, (uint64_t)k * 20));
        status(t, plc_timers_timer_memory_fr(&timers, 7, in(2, k % STEPS, tested, on)));
        status(t, plc_timers_timer_memory_start(&timers, 7, kind, in(0, k % STEPS, tested, on),
                                                0x0003));
        status(t, plc_timers_timer_memory_reset(&timers, 7, in(1, k % STEPS, tested, on)));
        status(t, plc_timers_timer_memory_status(&timers, 7, &q));
        status(t, plc_timers_timer_memory_load(&timers, 7, &bi));
        put(t, &q, sizeof q);
        put(t, &bi, sizeof bi);
        put(t, &timers, sizeof timers);
    }
}

/* ---- IEC timers --------------------------------------------------------------------------- */

/* TIME in ms, LTIME in ns: the same scenario, the times scaled by SCALE. */
#define IEC_TIMER_SCENARIO(NAME, TYPE, INPUT, OUTPUT, PT, ET, SCALE, CALL, RSR)                  \
    static void NAME(int kind, int tested, uint8_t on, struct trace *t) {                        \
        TYPE timer;                                                                              \
        memset(&timer, 0, sizeof timer);                                                         \
        for (int k = 0; k <= STEPS; k++) {                                                       \
            INPUT i;                                                                             \
            OUTPUT o;                                                                            \
            memset(&i, 0, sizeof i);                                                             \
            i.in = in(0, k % STEPS, tested, on);                                                 \
            i.r = in(1, k % STEPS, tested, on);                                                  \
            i.PT = 50 * (SCALE);                                                                 \
            status(t, CALL(&timer, kind, (uint64_t)k * 20 * (SCALE), i, &o));                    \
            put(t, &o.q, sizeof o.q);                                                            \
            put(t, &o.ET, sizeof o.ET);                                                          \
            put(t, &timer, sizeof timer);                                                        \
            /* RUN-STOP-RUN with `retentive` as field 2, every third step. */                    \
            if (k % 3 == 2) {                                                                    \
                status(t, RSR(&timer, in(2, k % STEPS, tested, on)));                            \
                put(t, &timer, sizeof timer);                                                    \
            }                                                                                    \
        }                                                                                        \
    }

IEC_TIMER_SCENARIO(iec_timer_ref, struct plc_timers_iec_timer_ref, struct plc_timers_iec_input,
                   struct plc_timers_iec_output, pt, et, 1, plc_timers_iec_timer_ref_call,
                   plc_timers_iec_timer_ref_run_stop_run)
IEC_TIMER_SCENARIO(iec_timer_opt, struct plc_timers_iec_timer, struct plc_timers_iec_input,
                   struct plc_timers_iec_output, pt, et, 1, plc_timers_iec_timer_call,
                   plc_timers_iec_timer_run_stop_run)
IEC_TIMER_SCENARIO(iec_ltimer_ref, struct plc_timers_iec_ltimer_ref,
                   struct plc_timers_iec_ltime_input, struct plc_timers_iec_ltime_output, pt_ns,
                   et_ns, 1000000, plc_timers_iec_ltimer_ref_call,
                   plc_timers_iec_ltimer_ref_run_stop_run)
IEC_TIMER_SCENARIO(iec_ltimer_opt, struct plc_timers_iec_ltimer, struct plc_timers_iec_ltime_input,
                   struct plc_timers_iec_ltime_output, pt_ns, et_ns, 1000000,
                   plc_timers_iec_ltimer_call, plc_timers_iec_ltimer_run_stop_run)

/* ---- IEC counters, every integer type ----------------------------------------------------- */

#define COUNTER_SCENARIO(NAME, TYPE, INPUT, OUTPUT, CALL)                                        \
    static void NAME(int kind, int tested, uint8_t on, struct trace *t) {                        \
        TYPE counter;                                                                            \
        memset(&counter, 0, sizeof counter);                                                     \
        for (int k = 0; k <= STEPS; k++) {                                                       \
            INPUT i;                                                                             \
            OUTPUT o;                                                                            \
            memset(&i, 0, sizeof i);                                                             \
            i.cu = in(0, k % STEPS, tested, on);                                                 \
            i.cd = in(1, k % STEPS, tested, on);                                                 \
            i.r = in(2, k % STEPS, tested, on);                                                  \
            i.ld = in(3, k % STEPS, tested, on);                                                 \
            i.pv = 2;                                                                            \
            status(t, CALL(&counter, kind, i, &o));                                              \
            put(t, &o.qu, sizeof o.qu);                                                          \
            put(t, &o.qd, sizeof o.qd);                                                          \
            put(t, &o.cv, sizeof o.cv);                                                          \
            put(t, &counter, sizeof counter);                                                    \
        }                                                                                        \
    }

#define COUNTER_TYPE(T)                                                                          \
    COUNTER_SCENARIO(counter_##T##_ref, plc_timers_counter_##T##_ref,                            \
                     plc_timers_counter_##T##_input, plc_timers_counter_##T##_output,            \
                     plc_timers_counter_##T##_ref_call)                                          \
    COUNTER_SCENARIO(counter_##T##_opt, plc_timers_counter_##T, plc_timers_counter_##T##_input,  \
                     plc_timers_counter_##T##_output, plc_timers_counter_##T##_call)

COUNTER_TYPE(sint)
COUNTER_TYPE(int)
COUNTER_TYPE(dint)
COUNTER_TYPE(lint)
COUNTER_TYPE(usint)
COUNTER_TYPE(uint)
COUNTER_TYPE(udint)
COUNTER_TYPE(ulint)

/* ---- S5 counters -------------------------------------------------------------------------- */

#define S5_COUNTER_SCENARIO(NAME, TYPE, INPUT, PV, PRESET, CALL)                                 \
    static void NAME(int kind, int tested, uint8_t on, struct trace *t) {                        \
        TYPE counter;                                                                            \
        memset(&counter, 0, sizeof counter);                                                     \
        for (int k = 0; k <= STEPS; k++) {                                                       \
            INPUT i;                                                                             \
            struct plc_timers_s5_counter_output o;                                               \
            memset(&i, 0, sizeof i);                                                             \
            i.cu = in(0, k % STEPS, tested, on);                                                 \
            i.cd = in(1, k % STEPS, tested, on);                                                 \
            i.s = in(2, k % STEPS, tested, on);                                                  \
            i.r = in(3, k % STEPS, tested, on);                                                  \
            i.fr = in(4, k % STEPS, tested, on);                                                 \
            i.PV = PRESET;                                                                       \
            status(t, CALL(&counter, kind, i, &o));                                              \
            put(t, &o.q, sizeof o.q);                                                            \
            put(t, &o.cv, sizeof o.cv);                                                          \
            put(t, &o.cv_bcd, sizeof o.cv_bcd);                                                  \
            put(t, &counter, sizeof counter);                                                    \
        }                                                                                        \
    }

S5_COUNTER_SCENARIO(s5_counter_ref, struct plc_timers_s5_counter_ref,
                    struct plc_timers_s5_counter_input, pv, 12, plc_timers_s5_counter_ref_call)
S5_COUNTER_SCENARIO(s5_counter_opt, struct plc_timers_s5_counter,
                    struct plc_timers_s5_counter_input, pv, 12, plc_timers_s5_counter_call)
S5_COUNTER_SCENARIO(s5_counter_ref_bcd, struct plc_timers_s5_counter_ref,
                    struct plc_timers_s5_counter_input_bcd, pv_bcd, 0x0012,
                    plc_timers_s5_counter_ref_call_bcd)
S5_COUNTER_SCENARIO(s5_counter_opt_bcd, struct plc_timers_s5_counter,
                    struct plc_timers_s5_counter_input_bcd, pv_bcd, 0x0012,
                    plc_timers_s5_counter_call_bcd)

#define COUNTER_MEMORY_CALL(NAME, CALL)                                                          \
    static void NAME##_area(int kind, int tested, uint8_t on, struct trace *t) {                 \
        (void)0;                                                                                 \
        memset(&counters, 0, sizeof counters);                                                   \
        for (int k = 0; k <= STEPS; k++) {                                                       \
            struct plc_timers_s5_counter_input i;                                                \
            struct plc_timers_s5_counter_input_bcd ib;                                           \
            struct plc_timers_s5_counter_output o;                                               \
            memset(&i, 0, sizeof i);                                                             \
            i.cu = in(0, k % STEPS, tested, on);                                                 \
            i.cd = in(1, k % STEPS, tested, on);                                                 \
            i.s = in(2, k % STEPS, tested, on);                                                  \
            i.r = in(3, k % STEPS, tested, on);                                                  \
            i.fr = in(4, k % STEPS, tested, on);                                                 \
            i.pv = 12;                                                                           \
            memset(&ib, 0, sizeof ib);                                                           \
            ib.cu = i.cu;                                                                        \
            ib.cd = i.cd;                                                                        \
            ib.s = i.s;                                                                          \
            ib.r = i.r;                                                                          \
            ib.fr = i.fr;                                                                        \
            ib.pv_bcd = 0x0012;                                                                  \
            status(t, CALL);                                                                     \
            put(t, &o.q, sizeof o.q);                                                            \
            put(t, &o.cv, sizeof o.cv);                                                          \
            put(t, &o.cv_bcd, sizeof o.cv_bcd);                                                  \
            put(t, &counters, sizeof counters);                                                  \
        }                                                                                        \
    }

COUNTER_MEMORY_CALL(counter_memory_call, plc_timers_counter_memory_call(&counters, 9, kind, i, &o))
COUNTER_MEMORY_CALL(counter_memory_call_bcd,
                    plc_timers_counter_memory_call_bcd(&counters, 9, kind, ib, &o))

/* The counters' STL operations' RLO parameters: FR, CU, CD, S (count and BCD forms), R. */
static void counter_memory_stl(int kind, int tested, uint8_t on, struct trace *t) {
    memset(&counters, 0, sizeof counters);
    for (int k = 0; k <= STEPS; k++) {
        bool q;
        uint16_t cv;
        int s = k % STEPS;
        status(t, plc_timers_counter_memory_fr(&counters, 9, in(4, s, tested, on)));
        status(t, plc_timers_counter_memory_cu(&counters, 9, in(0, s, tested, on)));
        status(t, plc_timers_counter_memory_cd(&counters, 9, in(1, s, tested, on)));
        if (kind == 0)
            status(t, plc_timers_counter_memory_set(&counters, 9, in(2, s, tested, on), 12));
        else
            status(t, plc_timers_counter_memory_set_bcd(&counters, 9, in(2, s, tested, on), 0x12));
        status(t, plc_timers_counter_memory_reset(&counters, 9, in(3, s, tested, on)));
        status(t, plc_timers_counter_memory_status(&counters, 9, &q));
        status(t, plc_timers_counter_memory_load(&counters, 9, &cv));
        put(t, &q, sizeof q);
        put(t, &cv, sizeof cv);
        put(t, &counters, sizeof counters);
    }
}

static const struct block BLOCKS[] = {
    {"S5 timer (reference)", s5_timer_ref, 5, 3},
    {"S5 timer (optimized)", s5_timer_opt, 5, 3},
    {"timer memory box", timer_memory_call, 5, 3},
    {"timer memory STL (FR, SP..SF, R)", timer_memory_stl, 5, 3},
    {"IEC timer (reference) + RUN-STOP-RUN", iec_timer_ref, 4, 3},
    {"IEC timer (optimized) + RUN-STOP-RUN", iec_timer_opt, 4, 3},
    {"IEC timer on LTIME (reference) + RUN-STOP-RUN", iec_ltimer_ref, 4, 3},
    {"IEC timer on LTIME (optimized) + RUN-STOP-RUN", iec_ltimer_opt, 4, 3},
#define COUNTER_BLOCKS(T)                                                                        \
    {"IEC counter " #T " (reference)", counter_##T##_ref, 3, 4},                                 \
        {"IEC counter " #T " (optimized)", counter_##T##_opt, 3, 4}
    COUNTER_BLOCKS(sint),
    COUNTER_BLOCKS(int),
    COUNTER_BLOCKS(dint),
    COUNTER_BLOCKS(lint),
    COUNTER_BLOCKS(usint),
    COUNTER_BLOCKS(uint),
    COUNTER_BLOCKS(udint),
    COUNTER_BLOCKS(ulint),
    {"S5 counter (reference)", s5_counter_ref, 3, 5},
    {"S5 counter (optimized)", s5_counter_opt, 3, 5},
    {"S5 counter (reference, BCD preset)", s5_counter_ref_bcd, 3, 5},
    {"S5 counter (optimized, BCD preset)", s5_counter_opt_bcd, 3, 5},
    {"counter memory box", counter_memory_call_area, 3, 5},
    {"counter memory box (BCD preset)", counter_memory_call_bcd_area, 3, 5},
    {"counter memory STL (FR, CU, CD, S, R; kind 1: S with a BCD word)", counter_memory_stl, 2,
     5},
};

static struct trace got, want, zero;

/* Every byte, or with `quick` (the run under valgrind) the bytes 0x00, 0x01, 0x02, 0x80, 0xFF. */
static void every_byte(int quick) {
    static const int QUICK[] = {0x00, 0x01, 0x02, 0x80, 0xFF};
    long runs = 0;
    for (size_t n = 0; n < sizeof BLOCKS / sizeof BLOCKS[0]; n++) {
        const struct block *b = &BLOCKS[n];
        int effect = 0;
        for (int kind = 0; kind < b->kinds; kind++) {
            for (int f = 0; f < b->fields; f++) {
                memset(&zero, 0, sizeof zero);
                b->run(kind, f, 0, &zero);
                for (int x = 0; x < (quick ? 5 : 0x100); x++) {
                    int v = quick ? QUICK[x] : x;
                    memset(&got, 0, sizeof got);
                    memset(&want, 0, sizeof want);
                    b->run(kind, f, (uint8_t)v, &got);
                    b->run(kind, f, v != 0, &want);
                    runs++;
                    CHECK(!got.bad_status && !want.bad_status,
                          "%s kind %d field %d byte 0x%02X: a status other than OK", b->name,
                          kind, f, v);
                    CHECK(got.len == want.len && memcmp(got.bytes, want.bytes, got.len) == 0,
                          "%s kind %d field %d byte 0x%02X: not as %d", b->name, kind, f, v,
                          v != 0);
                    if (v == 1 && (zero.len != got.len || memcmp(zero.bytes, got.bytes, got.len)))
                        effect = 1;
                }
            }
        }
        CHECK(effect, "%s: no input field changes anything (a vacuous scenario)", b->name);
    }
    printf("%s: %zu blocks, %ld runs compared\n",
           quick ? "bytes 0x00, 0x01, 0x02, 0x80, 0xFF" : "every byte 0x00-0xFF",
           sizeof BLOCKS / sizeof BLOCKS[0], runs);
}

/* ---- The clock going back (S5TMR-CLOCK-01) ------------------------------------------------- */

static void backward_clock(void) {
    static const uint64_t at[] = {0, 600, 100, 600, 990, 1000};
    static const int fired[] = {0, 0, 0, 0, 0, 1};
    struct plc_timers_s5_timer_ref r;
    struct plc_timers_s5_timer o;
    memset(&r, 0, sizeof r);
    memset(&o, 0, sizeof o);
    memset(&timers, 0, sizeof timers);
    struct plc_timers_s5_input i = {1, 0, 0, 0x0100}; /* S5T#1S: 100 x 10 ms */
    for (size_t k = 0; k < sizeof at / sizeof at[0]; k++) {
        struct plc_timers_s5_output a, b, c;
        CHECK(plc_timers_s5_timer_ref_call(&r, PLC_TIMERS_S_ODT, at[k], i, &a) == PLC_TIMERS_OK,
              "call");
        CHECK(plc_timers_s5_timer_call(&o, PLC_TIMERS_S_ODT, at[k], i, &b) == PLC_TIMERS_OK,
              "call");
        CHECK(plc_timers_timer_memory_call(&timers, 0, PLC_TIMERS_S_ODT, at[k], i, &c) ==
                  PLC_TIMERS_OK,
              "call");
        CHECK(a.q == fired[k] && b.q == fired[k] && c.q == fired[k],
              "S5TMR-CLOCK-01: at %d ms Q should be %d: reference %d, optimized %d, area %d",
              (int)at[k], fired[k], a.q, b.q, c.q);
        CHECK(a.bi == b.bi && a.bi == c.bi, "S5TMR-CLOCK-01: BI %d %d %d", a.bi, b.bi, c.bi);
    }
    CHECK(r.last_call_ms == 1000 && o.last_call_ms == 1000, "S5TMR-CLOCK-01: latest time kept");

    /* IEC: 1 ms behind START is 2^32 - 1 ms later on the 32-bit clock: a running TON expires. */
    struct plc_timers_iec_timer ton;
    struct plc_timers_iec_timer_ref ton_ref;
    struct plc_timers_iec_input on = {1, 0, 500};
    struct plc_timers_iec_output x, y;
    memset(&ton, 0, sizeof ton);
    memset(&ton_ref, 0, sizeof ton_ref);
    plc_timers_iec_timer_call(&ton, PLC_TIMERS_TON, 1000, on, &x);
    plc_timers_iec_timer_ref_call(&ton_ref, PLC_TIMERS_TON, 1000, on, &y);
    CHECK(!x.q && !y.q, "TON just started");
    CHECK(plc_timers_iec_timer_call(&ton, PLC_TIMERS_TON, 999, on, &x) == PLC_TIMERS_OK, "call");
    CHECK(plc_timers_iec_timer_ref_call(&ton_ref, PLC_TIMERS_TON, 999, on, &y) == PLC_TIMERS_OK,
          "call");
    CHECK(x.q && x.et == 500 && y.q && y.et == 500,
          "S5TMR-CLOCK-01 / IEC-WRAP-01: a clock behind START reads as the wrap");

    /* The same on LTIME's 64-bit nanosecond clock: 1 ns behind START is 2^64 - 1 ns later. */
    struct plc_timers_iec_ltimer lton;
    struct plc_timers_iec_ltimer_ref lton_ref;
    struct plc_timers_iec_ltime_input lon = {1, 0, 500000000};
    struct plc_timers_iec_ltime_output lx, ly;
    memset(&lton, 0, sizeof lton);
    memset(&lton_ref, 0, sizeof lton_ref);
    plc_timers_iec_ltimer_call(&lton, PLC_TIMERS_TON, 1000000000, lon, &lx);
    plc_timers_iec_ltimer_ref_call(&lton_ref, PLC_TIMERS_TON, 1000000000, lon, &ly);
    CHECK(!lx.q && !ly.q, "TON on LTIME just started");
    CHECK(plc_timers_iec_ltimer_call(&lton, PLC_TIMERS_TON, 999999999, lon, &lx) == PLC_TIMERS_OK,
          "call");
    CHECK(plc_timers_iec_ltimer_ref_call(&lton_ref, PLC_TIMERS_TON, 999999999, lon, &ly) ==
              PLC_TIMERS_OK,
          "call");
    CHECK(lx.q && lx.et_ns == 500000000 && ly.q && ly.et_ns == 500000000,
          "S5TMR-CLOCK-01 / IEC-WRAP-01: on LTIME a clock behind START reads as the wrap");
}

int main(int argc, char **argv) {
    every_byte(argc > 1 && strcmp(argv[1], "quick") == 0);
    backward_clock();
    printf("%d checks, %d failed\n", checks, failures);
    return failures != 0;
}
