/* libFuzzer target: the CSV reader of fmi2sim (see harness.c). */
#include "harness.h"
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) { return rw_fuzz_csv(data, size); }
