/*
 * How a soft-PLC runtime's generated scan code calls TON from plc-timers.
 *
 * A compiler of IEC 61131-3 to C (matiec, as OpenPLC uses it, works this way) turns each program
 * or function block into a struct of its variables, its instance data, with an init function
 * and a body function that the runtime calls once per scan. A TON instance declared in the
 * program becomes a member of that struct. Here the member is the 16-byte IEC_TIMER of
 * plc-timers, and the body calls plc_timers_iec_timer_call on it with the CPU time of the scan:
 * no allocation, no handle, no clock read inside the block.
 *
 * The program:
 *     PROGRAM lamp_delay
 *       VAR_INPUT  button : BOOL; END_VAR
 *       VAR_OUTPUT lamp : BOOL; lamp_et : TIME; END_VAR
 *       VAR delay : TON; END_VAR
 *       delay(IN := button, PT := T#500MS);
 *       lamp := delay.Q;  lamp_et := delay.ET;
 *     END_PROGRAM
 *
 * The scans below run at the times of examples/traces/ton.csv, and the output is printed as
 * `plc-timers run TON --pt T#500ms examples/traces/ton.csv` prints it (bindings/c/ci.sh compares
 * the two).
 *
 * Build (after `cargo build -p plc-timers-c --release`, from the repository's root):
 *     cc -Wall -Wextra -Ibindings/c/include examples/c/openplc_ton.c \
 *        target/release/libplc_timers.a -lpthread -ldl -lm -o openplc_ton
 */
#include "plc_timers.h"

#include <inttypes.h>
#include <stdio.h>
#include <string.h>

/* The instance data of the program, as the compiler lays it out. */
typedef struct {
    bool button;                /* VAR_INPUT */
    bool lamp;                  /* VAR_OUTPUT */
    int32_t lamp_et;            /* VAR_OUTPUT, TIME in ms */
    int32_t delay_pt;           /* the constant T#500MS, parsed once */
    plc_timers_iec_timer delay; /* VAR delay : TON (the S7-1200 IEC_TIMER, 16 bytes) */
} lamp_delay;

/* Reports a status that is not PLC_TIMERS_OK, as a runtime would log a fault. */
static int fault(const char *where, plc_timers_status status) {
    fprintf(stderr, "lamp_delay: %s: %s\n", where, plc_timers_status_message(status));
    return 1;
}

/* The generated init: zeroed instance data is the timer's initial state; the init call says so
 * explicitly. The literal is parsed by the library, with the error's byte position. */
static int lamp_delay_init(lamp_delay *data) {
    memset(data, 0, sizeof *data);
    size_t at = 0;
    plc_timers_status s = plc_timers_time_parse("T#500MS", &data->delay_pt, &at);
    if (s != PLC_TIMERS_OK) return fault("PT literal", s);
    s = plc_timers_iec_timer_init(&data->delay);
    return s == PLC_TIMERS_OK ? 0 : fault("TON init", s);
}

/* The generated body, called once per scan with the CPU time in ms. */
static int lamp_delay_body(lamp_delay *data, uint64_t now_ms) {
    plc_timers_iec_input in = {.in = data->button, .pt = data->delay_pt};
    plc_timers_iec_output out;
    plc_timers_status s = plc_timers_iec_timer_call(&data->delay, PLC_TIMERS_TON, now_ms, in, &out);
    if (s != PLC_TIMERS_OK) return fault("TON", s);
    data->lamp = out.q;
    data->lamp_et = (int32_t)out.et; /* ET <= PT <= INT32_MAX */
    return 0;
}

int main(void) {
    /* The runtime's scans: the CPU time of each and the button as read from the inputs. */
    static const struct {
        uint64_t t_ms;
        bool button;
    } scans[] = {{0, 0},    {1000, 1}, {1200, 1}, {1300, 0}, {2000, 1}, {2250, 1},
                 {2499, 1}, {2500, 1}, {3000, 1}, {3200, 0}, {3300, 0}};
    lamp_delay program;
    if (lamp_delay_init(&program)) return 1;
    printf("t_ms,IN,Q,ET\n");
    for (size_t i = 0; i < sizeof scans / sizeof scans[0]; i++) {
        program.button = scans[i].button; /* the runtime copies the input image */
        if (lamp_delay_body(&program, scans[i].t_ms)) return 1;
        printf("%" PRIu64 ",%d,%d,%" PRId32 "\n", scans[i].t_ms, program.button, program.lamp,
               program.lamp_et);
    }
    return 0;
}
