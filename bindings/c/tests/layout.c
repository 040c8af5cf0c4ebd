/*
 * The layout of every struct of the header, checked at compile time (C11 _Static_assert): the
 * sizes, alignments and field offsets that follow from the Rust side's #[repr(C)] field lists
 * (bindings/c/src), worked out here by the C rules (each field at the next multiple of its
 * alignment, the struct padded to its largest alignment). A header that no longer matches them
 * fails to compile; the program only reports that it was built.
 */
#include "plc_timers.h"

#include <stdalign.h>
#include <stddef.h>
#include <stdio.h>

#define LAYOUT(T, SIZE, ALIGN)                                                                   \
    _Static_assert(sizeof(T) == (SIZE), "size of " #T);                                          \
    _Static_assert(alignof(T) == (ALIGN), "alignment of " #T)
#define AT(T, FIELD, OFFSET) _Static_assert(offsetof(T, FIELD) == (OFFSET), #T "." #FIELD)

/* State structs: u64 + u16 + 6 x u8; u64 + u32 + u32; 3 x u32 + 4 x u8 (the manual's 16-byte
 * IEC_TIMER); 3 x u32 + u8 + u8[3]. */
LAYOUT(plc_timers_s5_timer_ref, 16, 8);
AT(plc_timers_s5_timer_ref, value, 8);
AT(plc_timers_s5_timer_ref, fr_prev, 15);
LAYOUT(plc_timers_s5_timer, 16, 8);
AT(plc_timers_s5_timer, word, 8);
LAYOUT(plc_timers_iec_timer_ref, 16, 4);
AT(plc_timers_iec_timer_ref, kind, 12);
AT(plc_timers_iec_timer_ref, q, 15);
LAYOUT(plc_timers_iec_timer, 16, 4);
AT(plc_timers_iec_timer, start, 0);
AT(plc_timers_iec_timer, pt, 4);
AT(plc_timers_iec_timer, et, 8);
AT(plc_timers_iec_timer, flags, 12);
/* The S7-1500 IEC_LTIMER (32 bytes): 3 x u64 + 4 x u8 + u8[4]; 3 x u64 + u8 + u8[7]. */
LAYOUT(plc_timers_iec_ltimer_ref, 32, 8);
AT(plc_timers_iec_ltimer_ref, kind, 24);
AT(plc_timers_iec_ltimer_ref, q, 27);
AT(plc_timers_iec_ltimer_ref, reserved, 28);
LAYOUT(plc_timers_iec_ltimer, 32, 8);
AT(plc_timers_iec_ltimer, start, 0);
AT(plc_timers_iec_ltimer, pt, 8);
AT(plc_timers_iec_ltimer, et, 16);
AT(plc_timers_iec_ltimer, flags, 24);
AT(plc_timers_iec_ltimer, reserved, 25);
/* u16 + 4 x u8; u16. */
LAYOUT(plc_timers_s5_counter_ref, 6, 2);
LAYOUT(plc_timers_s5_counter, 2, 2);
/* Memory areas: u64 + 256 x u32; 256 x u16. */
LAYOUT(plc_timers_timer_memory, 1032, 8);
AT(plc_timers_timer_memory, words, 8);
LAYOUT(plc_timers_counter_memory, 512, 2);

/* IEC counters: the reference holds CV and two edge memories of CV's type, the optimized form
 * CV and an edge word of CV's type; no padding in either. */
#define COUNTER(T, N, PV_AT, CV_AT)                                                           \
    LAYOUT(plc_timers_counter_##T##_ref, 3 * (N), (N));                                          \
    LAYOUT(plc_timers_counter_##T, 2 * (N), (N));                                                \
    LAYOUT(plc_timers_counter_##T##_input, (PV_AT) + (N), (N));                                  \
    AT(plc_timers_counter_##T##_input, pv, PV_AT);                                               \
    LAYOUT(plc_timers_counter_##T##_output, (CV_AT) + (N), (N));                                 \
    AT(plc_timers_counter_##T##_output, cv, CV_AT)
/* Input: 4 x u8 (CU, CD, R, LD), then PV at the next multiple of its size. Output: 2 x bool
 * (QU, QD), then CV likewise. */
COUNTER(sint, 1, 4, 2);
COUNTER(usint, 1, 4, 2);
COUNTER(int, 2, 4, 2);
COUNTER(uint, 2, 4, 2);
COUNTER(dint, 4, 4, 4);
COUNTER(udint, 4, 4, 4);
COUNTER(lint, 8, 8, 8);
COUNTER(ulint, 8, 8, 8);

/* Inputs: input bits are uint8_t (issue 37), one byte each, then the preset. */
LAYOUT(plc_timers_s5_input, 6, 2); /* 3 x u8, pad, u16 */
_Static_assert(sizeof(((plc_timers_s5_input *)0)->s) == 1, "S is a byte");
AT(plc_timers_s5_input, tv, 4);
LAYOUT(plc_timers_iec_input, 8, 4); /* 2 x u8, pad 2, i32 */
_Static_assert(sizeof(((plc_timers_iec_input *)0)->in) == 1, "IN is a byte");
AT(plc_timers_iec_input, pt, 4);
LAYOUT(plc_timers_iec_ltime_input, 16, 8); /* 2 x u8, pad 6, i64 */
_Static_assert(sizeof(((plc_timers_iec_ltime_input *)0)->in) == 1, "IN is a byte");
AT(plc_timers_iec_ltime_input, pt_ns, 8);
LAYOUT(plc_timers_s5_counter_input, 8, 2); /* 5 x u8, pad, u16 */
AT(plc_timers_s5_counter_input, pv, 6);
LAYOUT(plc_timers_s5_counter_input_bcd, 8, 2);
AT(plc_timers_s5_counter_input_bcd, pv_bcd, 6);
/* Outputs: bool then the values. */
LAYOUT(plc_timers_s5_output, 6, 2);
LAYOUT(plc_timers_iec_output, 8, 4);
LAYOUT(plc_timers_iec_ltime_output, 16, 8);
AT(plc_timers_iec_ltime_output, et_ns, 8);
LAYOUT(plc_timers_s5_counter_output, 6, 2);
/* The two preset representations are 16-bit words. */
_Static_assert(sizeof(plc_timers_s5_count) == 2 && sizeof(plc_timers_bcd_word) == 2, "words");

int main(void) {
    printf("layout: every size, alignment and offset as the Rust side defines it\n");
    return 0;
}
