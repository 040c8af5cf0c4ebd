/*
 * The harness around the README's C block (bindings/c/ci.sh extracts it into its own file and
 * links it with this one): its `scan` is called every 100 ms for 1 s of CPU time with the input
 * byte 0xFF (a process-image byte; any byte but 0 is TRUE), then with a corrupted instance.
 * The expected values are the S7-1200 manual's TON: Q rises when ET reaches PT, 500 ms after IN
 * rose; a call that fails writes nothing, so the lamp keeps its value. valgrind (memcheck)
 * reports any read of an uninitialised `out`.
 */
#include "plc_timers.h"

#include <stdio.h>
#include <string.h>

extern plc_timers_iec_timer ton;
void scan(uint8_t button, uint64_t now_ms, uint8_t *lamp);

int main(void) {
    uint8_t lamp = 0;
    int failures = 0;
    for (uint64_t t = 0; t <= 1000; t += 100) {
        scan(0xFF, t, &lamp);
        if (lamp != (t >= 500)) {
            fprintf(stderr, "at %u ms the lamp is %d, expected %d\n", (unsigned)t, lamp, t >= 500);
            failures++;
        }
    }
    /* A corrupted instance (a flag bit no state has): the call reports it, the lamp stays 1. */
    ton.flags = 0xFF;
    scan(0, 1100, &lamp);
    if (lamp != 1) {
        fprintf(stderr, "after a failed call the lamp changed to %d\n", lamp);
        failures++;
    }
    printf("README scan code: TON on at 500 ms, a fault keeps the lamp: %s\n",
           failures ? "FAILED" : "ok");
    return failures != 0;
}
