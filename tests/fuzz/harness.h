/* Entry points of the input-reader fuzzing harness (harness.c). */
#ifndef RW_FUZZ_HARNESS_H
#define RW_FUZZ_HARNESS_H
#include <stddef.h>
#include <stdint.h>
int rw_fuzz_csv(const uint8_t *data, size_t size);
int rw_fuzz_at2(const uint8_t *data, size_t size);
#endif
