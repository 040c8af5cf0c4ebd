/*
 * A program built against an installed copy of the library (bindings/c/ci.sh builds it with
 * pkg-config and with CMake's find_package): the header and the library linked are the same
 * version, and a TON with PT 500 ms runs out 500 ms after IN rises (S7-1200 manual, TON).
 */
#include <plc_timers.h>

#include <stdio.h>

int main(void) {
    if (plc_timers_version() != PLC_TIMERS_VERSION) {
        fprintf(stderr, "header %d, library %u\n", PLC_TIMERS_VERSION,
                (unsigned)plc_timers_version());
        return 1;
    }
    plc_timers_iec_timer ton = {0, 0, 0, 0, {0, 0, 0}};
    plc_timers_iec_input in = {1, 0, 500};
    plc_timers_iec_output out;
    for (unsigned t = 0; t <= 500; t += 100) {
        if (plc_timers_iec_timer_call(&ton, PLC_TIMERS_TON, t, in, &out) != PLC_TIMERS_OK)
            return 1;
        if (out.q != (t == 500)) {
            fprintf(stderr, "TON at %u ms: Q = %d\n", t, out.q);
            return 1;
        }
    }
    printf("plc_timers %d.%d.%d: TON ran out at 500 ms\n", PLC_TIMERS_VERSION_MAJOR,
           PLC_TIMERS_VERSION_MINOR, PLC_TIMERS_VERSION_PATCH);
    return 0;
}
