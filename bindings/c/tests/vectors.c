/*
 * Replays every test vector file through the C API and compares every output.
 *
 * Usage: vectors DIR, where DIR holds the vectors `plc-timers vectors DIR` writes: one
 * directory per block (IEC counters: per integer type, e.g. CTUD-SINT), CSV files whose columns
 * are the inputs, the preset and the reference outputs (spec/cli.md, README.txt of DIR); the IEC
 * timers' files may have an RT column, the -(RT)- coil, applied with the C API's reset.
 *
 * Every row runs through every form of the block, each on its own state: the reference and the
 * optimized form, and for the S5 timers and counters also a box call on a memory area; the IEC
 * timers' rows also through the LTIME timers, scaled to nanoseconds (see replay_iec_timer),
 * and the LTIME vectors (`TON-LTIME`, ...: t_ns) through the LTIME timers as written. The
 * presets are parsed by the C API's parsers. Every output of every row is compared with the
 * file; every call must return PLC_TIMERS_OK. Exit status 0 when all agree, 1 on any
 * difference (each reported with file, line and column), 2 on a malformed file or directory.
 */
#include "plc_timers.h"

#include <ctype.h>
#include <dirent.h>
#include <errno.h>
#include <inttypes.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MAX_LINE 1024
#define MAX_FIELDS 16
#define MAX_REPORTS 20

static unsigned long files, rows, comparisons, failures, rt_rows;

/* One CSV file: its header and the current row, split into fields. */
typedef struct {
    const char *path;
    FILE *f;
    unsigned long line;
    char header_line[MAX_LINE];
    char row_line[MAX_LINE];
    char *header[MAX_FIELDS];
    char *field[MAX_FIELDS];
    int columns;
} csv;

static void die(const char *path, unsigned long line, const char *what) {
    fprintf(stderr, "%s:%lu: %s\n", path, line, what);
    exit(2);
}

static int split(char *line, char **out) {
    int n = 0;
    line[strcspn(line, "\r\n")] = '\0';
    for (char *p = line;; n++) {
        if (n == MAX_FIELDS) return -1;
        out[n] = p;
        char *comma = strchr(p, ',');
        if (!comma) return n + 1;
        *comma = '\0';
        p = comma + 1;
    }
}

static void csv_open(csv *c, const char *path) {
    memset(c, 0, sizeof *c);
    c->path = path;
    c->f = fopen(path, "r");
    if (!c->f) die(path, 0, strerror(errno));
    if (!fgets(c->header_line, sizeof c->header_line, c->f)) die(path, 1, "no header");
    c->line = 1;
    c->columns = split(c->header_line, c->header);
    if (c->columns < 0) die(path, 1, "too many columns");
}

/* Reads the next row; 0 at the end of the file. */
static int csv_next(csv *c) {
    if (!fgets(c->row_line, sizeof c->row_line, c->f)) return 0;
    c->line++;
    if (split(c->row_line, c->field) != c->columns) die(c->path, c->line, "wrong number of fields");
    return 1;
}

static void csv_close(csv *c) { fclose(c->f); }

/* The index of column `name`, or -1 when the file has none. */
static int column(const csv *c, const char *name) {
    for (int i = 0; i < c->columns; i++)
        if (strcmp(c->header[i], name) == 0) return i;
    return -1;
}

static int required(const csv *c, const char *name) {
    int i = column(c, name);
    if (i < 0) {
        fprintf(stderr, "%s: no column %s\n", c->path, name);
        exit(2);
    }
    return i;
}

/* A boolean cell (0/1); an absent column (index -1) is 0 on every row. */
static bool cell_bool(const csv *c, int i) {
    if (i < 0) return false;
    if (strcmp(c->field[i], "0") == 0) return false;
    if (strcmp(c->field[i], "1") == 0) return true;
    die(c->path, c->line, "a boolean cell is not 0 or 1");
    return false;
}

static uint64_t cell_u64(const csv *c, int i) {
    char *end;
    errno = 0;
    unsigned long long v = strtoull(c->field[i], &end, 10);
    if (errno || *end || end == c->field[i] || c->field[i][0] == '-')
        die(c->path, c->line, "not an unsigned integer");
    return (uint64_t)v;
}

static int64_t cell_i64(const csv *c, int i) {
    char *end;
    errno = 0;
    long long v = strtoll(c->field[i], &end, 10);
    if (errno || *end || end == c->field[i]) die(c->path, c->line, "not an integer");
    return (int64_t)v;
}

/* A `W#16#XXXX` cell. */
static uint16_t cell_word(const csv *c, int i) {
    const char *s = c->field[i];
    char *end;
    if (strncmp(s, "W#16#", 5) != 0) die(c->path, c->line, "not a W#16# word");
    unsigned long v = strtoul(s + 5, &end, 16);
    if (*end || v > 0xFFFF) die(c->path, c->line, "not a W#16# word");
    return (uint16_t)v;
}

static void check_status(const csv *c, const char *form, plc_timers_status s) {
    if (s != PLC_TIMERS_OK) {
        fprintf(stderr, "%s:%lu: %s: status %d: %s\n", c->path, c->line, form, (int)s,
                plc_timers_status_message(s));
        exit(1);
    }
}

/* Compares one output: `got` from form `form` with the file's cell in column `name`. */
static void compare(const csv *c, const char *form, const char *name, long long expected,
                    long long got) {
    comparisons++;
    if (expected == got) return;
    if (failures++ < MAX_REPORTS)
        fprintf(stderr, "%s:%lu: %s: column %s: expected %lld, got %lld\n", c->path, c->line, form,
                name, expected, got);
}

static void compare_u64(const csv *c, const char *form, const char *name, uint64_t expected,
                        uint64_t got) {
    comparisons++;
    if (expected == got) return;
    if (failures++ < MAX_REPORTS)
        fprintf(stderr, "%s:%lu: %s: column %s: expected %" PRIu64 ", got %" PRIu64 "\n", c->path,
                c->line, form, name, expected, got);
}

/* ------------------------------------------------------------------------------------------ */
/* S5 timers: reference, optimized, and T 17 of a timer memory area. */

static void replay_s5_timer(const char *path, int kind) {
    csv c;
    csv_open(&c, path);
    int t = required(&c, "t_ms"), s = required(&c, "S"), r = required(&c, "R");
    int fr = column(&c, "FR"), tv = required(&c, "TV");
    int q = required(&c, "Q"), bi = required(&c, "BI"), bcd = required(&c, "BCD");
    plc_timers_s5_timer_ref ref;
    plc_timers_s5_timer opt;
    static plc_timers_timer_memory area;
    check_status(&c, "ref init", plc_timers_s5_timer_ref_init(&ref));
    check_status(&c, "init", plc_timers_s5_timer_init(&opt));
    check_status(&c, "area init", plc_timers_timer_memory_init(&area));
    while (csv_next(&c)) {
        plc_timers_s5_input in = {.s = cell_bool(&c, s), .r = cell_bool(&c, r),
                                  .fr = cell_bool(&c, fr)};
        size_t at = 0;
        if (plc_timers_s5time_parse(c.field[tv], &in.tv, &at) != PLC_TIMERS_OK)
            die(c.path, c.line, "TV is not an S5TIME literal");
        uint64_t now = cell_u64(&c, t);
        plc_timers_s5_output out[3];
        check_status(&c, "reference", plc_timers_s5_timer_ref_call(&ref, kind, now, in, &out[0]));
        check_status(&c, "optimized", plc_timers_s5_timer_call(&opt, kind, now, in, &out[1]));
        check_status(&c, "memory area",
                     plc_timers_timer_memory_call(&area, 17, kind, now, in, &out[2]));
        const char *form[3] = {"reference", "optimized", "memory area T 17"};
        for (int i = 0; i < 3; i++) {
            compare(&c, form[i], "Q", cell_bool(&c, q), out[i].q);
            compare(&c, form[i], "BI", (long long)cell_u64(&c, bi), out[i].bi);
            compare(&c, form[i], "BCD", cell_word(&c, bcd), out[i].bcd);
        }
        rows++;
    }
    csv_close(&c);
}

/* ------------------------------------------------------------------------------------------ */
/* IEC timers: reference and optimized (IEC_TIMER). A row with RT = 1 (the optional column of
 * the -(RT)- coil, spec/cli.md "Traces") runs the coil before the box call, as a network above
 * the box's network would.
 *
 * The same trace also runs through the LTIME timers (IEC_LTIMER, both forms) scaled to
 * nanoseconds: every time and PT times 10^6 ns/ms, and each of their outputs is compared with
 * the file's, ET times 10^6 (the oracle is the TIME vectors, independent of the LTIME code).
 * That holds while the TIME timer's 32-bit millisecond clock cannot wrap within a running
 * timer: a running timer has ET below PT < 2^31 ms, so a step of less than 2^31 ms forward
 * never wraps. From a step of 2^31 ms or more (or backwards, or past 2^64 ns) on, the two
 * clocks part by design and the file's LTIME replay stops (counted as a cut). A PT cell that is
 * a `T#`/`TIME#` literal is also parsed as `LT#`/`LTIME#` by the LTIME parser, which must give
 * the TIME value in nanoseconds. */

#define NS_PER_MS 1000000
static unsigned long ltime_rows, ltime_cuts, ltime_literals;

/* The LTIME literal of TIME literal `time` (`T#...` or `TIME#...`, any case) in `out`; 0 when
 * `time` is not one (a plain number of milliseconds). */
static int has_prefix(const char *s, const char *prefix) {
    for (; *prefix; s++, prefix++)
        if (toupper((unsigned char)*s) != *prefix) return 0;
    return 1;
}

static int as_ltime_literal(const char *time, char *out, size_t size) {
    if (has_prefix(time, "T#") || has_prefix(time, "TIME#"))
        return snprintf(out, size, "L%s", time) < (int)size;
    return 0;
}

static void replay_iec_timer(const char *path, int kind) {
    csv c;
    csv_open(&c, path);
    int t = required(&c, "t_ms"), in_col = required(&c, "IN"), r = column(&c, "R");
    int rt = column(&c, "RT");
    int pt = required(&c, "PT"), q = required(&c, "Q"), et = required(&c, "ET");
    plc_timers_iec_timer_ref ref;
    plc_timers_iec_timer opt;
    plc_timers_iec_ltimer_ref lref;
    plc_timers_iec_ltimer lopt;
    check_status(&c, "ref init", plc_timers_iec_timer_ref_init(&ref));
    check_status(&c, "init", plc_timers_iec_timer_init(&opt));
    check_status(&c, "LTIME ref init", plc_timers_iec_ltimer_ref_init(&lref));
    check_status(&c, "LTIME init", plc_timers_iec_ltimer_init(&lopt));
    int scaled = 1, first = 1;
    uint64_t before = 0;
    while (csv_next(&c)) {
        plc_timers_iec_input in = {.in = cell_bool(&c, in_col), .r = cell_bool(&c, r)};
        if (plc_timers_time_parse(c.field[pt], &in.pt, NULL) != PLC_TIMERS_OK)
            die(c.path, c.line, "PT is not a TIME literal");
        uint64_t now = cell_u64(&c, t);
        int reset = cell_bool(&c, rt);
        if (reset) {
            check_status(&c, "reference RT", plc_timers_iec_timer_ref_reset(&ref));
            check_status(&c, "optimized RT", plc_timers_iec_timer_reset(&opt));
            rt_rows++;
        }
        plc_timers_iec_output out[2];
        check_status(&c, "reference", plc_timers_iec_timer_ref_call(&ref, kind, now, in, &out[0]));
        check_status(&c, "optimized", plc_timers_iec_timer_call(&opt, kind, now, in, &out[1]));
        const char *form[2] = {"reference", "optimized"};
        for (int i = 0; i < 2; i++) {
            compare(&c, form[i], "Q", cell_bool(&c, q), out[i].q);
            compare_u64(&c, form[i], "ET", cell_u64(&c, et), out[i].et);
        }
        rows++;

        /* The LTIME timers on the scaled row. */
        char ltime[MAX_LINE + 1];
        if (as_ltime_literal(c.field[pt], ltime, sizeof ltime)) {
            int64_t pt_ns = 0;
            size_t at = 0;
            plc_timers_status s = plc_timers_ltime_parse(ltime, &pt_ns, &at);
            comparisons++;
            ltime_literals++;
            if ((s != PLC_TIMERS_OK || pt_ns != (int64_t)in.pt * NS_PER_MS) &&
                failures++ < MAX_REPORTS)
                fprintf(stderr,
                        "%s:%lu: LTIME parser: %s: status %d at %zu, %" PRId64
                        " ns, expected %" PRId64 " ns\n",
                        c.path, c.line, ltime, (int)s, at, pt_ns, (int64_t)in.pt * NS_PER_MS);
        }
        if (scaled && (now > UINT64_MAX / NS_PER_MS ||
                       (!first && (now < before || now - before >= (UINT64_C(1) << 31))))) {
            scaled = 0;
            ltime_cuts++;
        }
        first = 0;
        before = now;
        if (!scaled) continue;
        plc_timers_iec_ltime_input lin = {.in = in.in, .r = in.r, .pt_ns = (int64_t)in.pt * NS_PER_MS};
        uint64_t now_ns = now * NS_PER_MS;
        if (reset) {
            check_status(&c, "LTIME reference RT", plc_timers_iec_ltimer_ref_reset(&lref));
            check_status(&c, "LTIME optimized RT", plc_timers_iec_ltimer_reset(&lopt));
        }
        plc_timers_iec_ltime_output lout[2];
        check_status(&c, "LTIME reference",
                     plc_timers_iec_ltimer_ref_call(&lref, kind, now_ns, lin, &lout[0]));
        check_status(&c, "LTIME optimized",
                     plc_timers_iec_ltimer_call(&lopt, kind, now_ns, lin, &lout[1]));
        const char *lform[2] = {"LTIME reference (ns / 10^6)", "LTIME optimized (ns / 10^6)"};
        for (int i = 0; i < 2; i++) {
            compare(&c, lform[i], "Q", cell_bool(&c, q), lout[i].q);
            compare_u64(&c, lform[i], "ET (ns)", cell_u64(&c, et) * NS_PER_MS, lout[i].et_ns);
        }
        ltime_rows++;
    }
    csv_close(&c);
}

/* The IEC timers' LTIME vectors (`TP-LTIME`, ...): t_ns, IN, R, RT, PT (an LTIME literal or
 * integer ns), Q, ET (ns), through both IEC_LTIMER forms as written, with no scaling: the
 * presets past TIME's range and the gaps past 2^63 ns that only LTIME has. */
static unsigned long ltime_vector_rows;

static void replay_iec_ltimer(const char *path, int kind) {
    csv c;
    csv_open(&c, path);
    int t = required(&c, "t_ns"), in_col = required(&c, "IN"), r = column(&c, "R");
    int rt = column(&c, "RT");
    int pt = required(&c, "PT"), q = required(&c, "Q"), et = required(&c, "ET");
    plc_timers_iec_ltimer_ref ref;
    plc_timers_iec_ltimer opt;
    check_status(&c, "LTIME ref init", plc_timers_iec_ltimer_ref_init(&ref));
    check_status(&c, "LTIME init", plc_timers_iec_ltimer_init(&opt));
    while (csv_next(&c)) {
        plc_timers_iec_ltime_input in = {.in = cell_bool(&c, in_col), .r = cell_bool(&c, r)};
        if (plc_timers_ltime_parse(c.field[pt], &in.pt_ns, NULL) != PLC_TIMERS_OK)
            in.pt_ns = cell_i64(&c, pt);
        uint64_t now = cell_u64(&c, t);
        if (cell_bool(&c, rt)) {
            check_status(&c, "LTIME reference RT", plc_timers_iec_ltimer_ref_reset(&ref));
            check_status(&c, "LTIME optimized RT", plc_timers_iec_ltimer_reset(&opt));
            rt_rows++;
        }
        plc_timers_iec_ltime_output out[2];
        check_status(&c, "LTIME reference", plc_timers_iec_ltimer_ref_call(&ref, kind, now, in, &out[0]));
        check_status(&c, "LTIME optimized", plc_timers_iec_ltimer_call(&opt, kind, now, in, &out[1]));
        const char *form[2] = {"LTIME reference", "LTIME optimized"};
        for (int i = 0; i < 2; i++) {
            compare(&c, form[i], "Q", cell_bool(&c, q), out[i].q);
            compare_u64(&c, form[i], "ET (ns)", cell_u64(&c, et), out[i].et_ns);
        }
        rows++;
        ltime_vector_rows++;
    }
    csv_close(&c);
}

/* ------------------------------------------------------------------------------------------ */
/* IEC counters, one replay function per integer type. CV and PV are read as 64-bit integers
 * of the type's signedness and must fit the type. */

#define REPLAY_COUNTER(NAME, CTYPE, CELL, WIDE, FMT)                                     \
    static CTYPE NAME##_cell(const csv *c, int i) {                                              \
        WIDE v = CELL(c, i);                                                                     \
        /* It fits the type when the conversion to it and back keeps it. */                    \
        if ((WIDE)(CTYPE)v != v) die(c->path, c->line, "out of the type's range");              \
        return (CTYPE)v;                                                                         \
    }                                                                                            \
    static void replay_counter_##NAME(const char *path, int kind) {                              \
        csv c;                                                                                   \
        csv_open(&c, path);                                                                      \
        int cu = column(&c, "CU"), cd = column(&c, "CD"), r = column(&c, "R");                   \
        int ld = column(&c, "LD"), pv = required(&c, "PV"), cv = required(&c, "CV");             \
        int qu = kind == PLC_TIMERS_CTD ? -1 : required(&c, kind == PLC_TIMERS_CTU ? "Q" : "QU"); \
        int qd = kind == PLC_TIMERS_CTU ? -1 : required(&c, kind == PLC_TIMERS_CTD ? "Q" : "QD"); \
        plc_timers_counter_##NAME##_ref ref;                                                     \
        plc_timers_counter_##NAME opt;                                                           \
        check_status(&c, "ref init", plc_timers_counter_##NAME##_ref_init(&ref));                \
        check_status(&c, "init", plc_timers_counter_##NAME##_init(&opt));                        \
        while (csv_next(&c)) {                                                                   \
            plc_timers_counter_##NAME##_input in = {                                             \
                .cu = cell_bool(&c, cu), .cd = cell_bool(&c, cd), .r = cell_bool(&c, r),         \
                .ld = cell_bool(&c, ld), .pv = NAME##_cell(&c, pv)};                             \
            plc_timers_counter_##NAME##_output out[2];                                           \
            check_status(&c, "reference",                                                        \
                         plc_timers_counter_##NAME##_ref_call(&ref, kind, in, &out[0]));         \
            check_status(&c, "optimized", plc_timers_counter_##NAME##_call(&opt, kind, in, &out[1])); \
            const char *form[2] = {"reference", "optimized"};                                    \
            for (int i = 0; i < 2; i++) {                                                        \
                if (qu >= 0) compare(&c, form[i], c.header[qu], cell_bool(&c, qu), out[i].qu);   \
                if (qd >= 0) compare(&c, form[i], c.header[qd], cell_bool(&c, qd), out[i].qd);   \
                comparisons++;                                                                   \
                if (NAME##_cell(&c, cv) != out[i].cv && failures++ < MAX_REPORTS)                \
                    fprintf(stderr, "%s:%lu: %s: column CV: expected %s, got %" FMT "\n", c.path,  \
                            c.line, form[i], c.field[cv], (WIDE)out[i].cv);                      \
            }                                                                                    \
            rows++;                                                                              \
        }                                                                                        \
        csv_close(&c);                                                                           \
    }

REPLAY_COUNTER(sint, int8_t, cell_i64, int64_t, PRId64)
REPLAY_COUNTER(int, int16_t, cell_i64, int64_t, PRId64)
REPLAY_COUNTER(dint, int32_t, cell_i64, int64_t, PRId64)
REPLAY_COUNTER(lint, int64_t, cell_i64, int64_t, PRId64)
REPLAY_COUNTER(usint, uint8_t, cell_u64, uint64_t, PRIu64)
REPLAY_COUNTER(uint, uint16_t, cell_u64, uint64_t, PRIu64)
REPLAY_COUNTER(udint, uint32_t, cell_u64, uint64_t, PRIu64)
REPLAY_COUNTER(ulint, uint64_t, cell_u64, uint64_t, PRIu64)

/* ------------------------------------------------------------------------------------------ */
/* S5 counters: reference, optimized, and C 200 of a counter memory area. */

static void replay_s5_counter(const char *path, int kind) {
    csv c;
    csv_open(&c, path);
    int cu = column(&c, "CU"), cd = column(&c, "CD"), s = required(&c, "S"), r = required(&c, "R");
    int fr = column(&c, "FR"), pv = required(&c, "PV");
    int q = required(&c, "Q"), cv = required(&c, "CV"), cv_bcd = required(&c, "CV_BCD");
    plc_timers_s5_counter_ref ref;
    plc_timers_s5_counter opt;
    static plc_timers_counter_memory area;
    check_status(&c, "ref init", plc_timers_s5_counter_ref_init(&ref));
    check_status(&c, "init", plc_timers_s5_counter_init(&opt));
    check_status(&c, "area init", plc_timers_counter_memory_init(&area));
    while (csv_next(&c)) {
        plc_timers_s5_counter_input in = {.cu = cell_bool(&c, cu), .cd = cell_bool(&c, cd),
                                          .s = cell_bool(&c, s), .r = cell_bool(&c, r),
                                          .fr = cell_bool(&c, fr)};
        if (plc_timers_counter_preset_parse(c.field[pv], &in.pv) != PLC_TIMERS_OK)
            die(c.path, c.line, "PV is not a counter preset");
        plc_timers_s5_counter_output out[3];
        check_status(&c, "reference", plc_timers_s5_counter_ref_call(&ref, kind, in, &out[0]));
        check_status(&c, "optimized", plc_timers_s5_counter_call(&opt, kind, in, &out[1]));
        check_status(&c, "memory area", plc_timers_counter_memory_call(&area, 200, kind, in, &out[2]));
        const char *form[3] = {"reference", "optimized", "memory area C 200"};
        for (int i = 0; i < 3; i++) {
            compare(&c, form[i], "Q", cell_bool(&c, q), out[i].q);
            compare(&c, form[i], "CV", (long long)cell_u64(&c, cv), out[i].cv);
            compare(&c, form[i], "CV_BCD", cell_word(&c, cv_bcd), out[i].cv_bcd);
        }
        rows++;
    }
    csv_close(&c);
}

/* ------------------------------------------------------------------------------------------ */
/* The blocks, by directory name. */

typedef void (*replay_fn)(const char *path, int kind);

static const struct {
    const char *dir;
    replay_fn replay;
    int kind;
} BLOCKS[] = {
    {"S_PULSE", replay_s5_timer, PLC_TIMERS_S_PULSE},
    {"S_PEXT", replay_s5_timer, PLC_TIMERS_S_PEXT},
    {"S_ODT", replay_s5_timer, PLC_TIMERS_S_ODT},
    {"S_ODTS", replay_s5_timer, PLC_TIMERS_S_ODTS},
    {"S_OFFDT", replay_s5_timer, PLC_TIMERS_S_OFFDT},
    {"TP", replay_iec_timer, PLC_TIMERS_TP},
    {"TON", replay_iec_timer, PLC_TIMERS_TON},
    {"TOF", replay_iec_timer, PLC_TIMERS_TOF},
    {"TONR", replay_iec_timer, PLC_TIMERS_TONR},
    {"TP-LTIME", replay_iec_ltimer, PLC_TIMERS_TP},
    {"TON-LTIME", replay_iec_ltimer, PLC_TIMERS_TON},
    {"TOF-LTIME", replay_iec_ltimer, PLC_TIMERS_TOF},
    {"TONR-LTIME", replay_iec_ltimer, PLC_TIMERS_TONR},
#define COUNTER_BLOCKS(TYPE, NAME)                                                               \
    {"CTU-" TYPE, replay_counter_##NAME, PLC_TIMERS_CTU},                                        \
        {"CTD-" TYPE, replay_counter_##NAME, PLC_TIMERS_CTD},                                    \
        {"CTUD-" TYPE, replay_counter_##NAME, PLC_TIMERS_CTUD}
    COUNTER_BLOCKS("SINT", sint),
    COUNTER_BLOCKS("INT", int),
    COUNTER_BLOCKS("DINT", dint),
    COUNTER_BLOCKS("LINT", lint),
    COUNTER_BLOCKS("USINT", usint),
    COUNTER_BLOCKS("UINT", uint),
    COUNTER_BLOCKS("UDINT", udint),
    COUNTER_BLOCKS("ULINT", ulint),
    {"S_CU", replay_s5_counter, PLC_TIMERS_S_CU},
    {"S_CD", replay_s5_counter, PLC_TIMERS_S_CD},
    {"S_CUD", replay_s5_counter, PLC_TIMERS_S_CUD},
};
#define BLOCK_COUNT (sizeof BLOCKS / sizeof BLOCKS[0])

static int ends_with(const char *s, const char *suffix) {
    size_t n = strlen(s), m = strlen(suffix);
    return n >= m && strcmp(s + n - m, suffix) == 0;
}

int main(int argc, char **argv) {
    if (argc != 2) {
        fprintf(stderr, "usage: %s VECTORS_DIR (written by `plc-timers vectors VECTORS_DIR`)\n",
                argv[0]);
        return 2;
    }
    for (size_t b = 0; b < BLOCK_COUNT; b++) {
        char dir[4096];
        snprintf(dir, sizeof dir, "%s/%s", argv[1], BLOCKS[b].dir);
        DIR *d = opendir(dir);
        if (!d) die(dir, 0, "no vectors for this block");
        unsigned long block_files = 0, block_rows = rows;
        struct dirent *e;
        while ((e = readdir(d)) != NULL) {
            if (!ends_with(e->d_name, ".csv")) continue;
            char path[8192];
            snprintf(path, sizeof path, "%s/%s", dir, e->d_name);
            BLOCKS[b].replay(path, BLOCKS[b].kind);
            block_files++;
        }
        closedir(d);
        if (block_files == 0) die(dir, 0, "no vector files");
        files += block_files;
        printf("%-11s %3lu files %5lu rows\n", BLOCKS[b].dir, block_files, rows - block_rows);
    }
    /* Every directory of DIR is a block this program knows: a new block in the vectors must
     * get a replay here. */
    DIR *top = opendir(argv[1]);
    if (!top) die(argv[1], 0, strerror(errno));
    struct dirent *e;
    while ((e = readdir(top)) != NULL) {
        if (e->d_name[0] == '.' || strcmp(e->d_name, "README.txt") == 0) continue;
        int known = 0;
        for (size_t b = 0; b < BLOCK_COUNT; b++) known |= strcmp(e->d_name, BLOCKS[b].dir) == 0;
        if (!known) die(e->d_name, 0, "a vectors directory this test does not replay");
    }
    closedir(top);
    printf("%lu files, %lu rows (%lu with the RT coil), %lu outputs compared, %lu differences\n",
           files, rows, rt_rows, comparisons, failures);
    printf("LTIME: %lu rows of the LTIME vectors; %lu IEC timer rows replayed scaled to ns (%lu "
           "files cut at a step of 2^31 ms or more), %lu PT literals parsed as LTIME\n",
           ltime_vector_rows, ltime_rows, ltime_cuts, ltime_literals);
    /* The IEC timers' decisions.csv set the RT coil: a replay that never applied it did not
     * replay them. */
    if (rt_rows == 0) die(argv[1], 0, "no row with RT = 1: the RT column was not replayed");
    /* Likewise the LTIME replay must have run (a cut of every file would test nothing). */
    if (ltime_rows == 0 || ltime_literals == 0 || ltime_vector_rows == 0)
        die(argv[1], 0, "no IEC timer row replayed on LTIME");
    return failures ? 1 : 0;
}
