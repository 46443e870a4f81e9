/* Input signals: columns of samples in time, linearly interpolated (continuous inputs) or held
 * (discrete ones), ends held. Two samples of one time are a step: the first is the value up to
 * it, the second the value from it on. */
#ifndef FMI2SIM_INPUT_TABLE_H
#define FMI2SIM_INPUT_TABLE_H

#include <stddef.h>

typedef struct {
    char *name;      /* the FMU input variable it drives */
    double *values;  /* one per time sample */
} input_column;

typedef struct {
    char *source;    /* the file it was read from */
    double *t;       /* increasing sample times; a time at most twice in a row (a step) */
    size_t n;        /* samples */
    input_column *cols;
    size_t ncols;
} input_table;

/* CSV: header "time,NAME,...", then numeric rows; errors name FILE:LINE. */
int input_read_csv(const char *path, input_table *tab, char *err, size_t n);
/* PEER NGA .AT2 (acceleration in g): one column named `name`, values * g * scale. */
int input_read_at2(const char *path, const char *name, double g, double scale, input_table *tab,
                   char *err, size_t n);
/* Continuous inputs: linear between samples; at a step the value from it on (input_value) or
 * the limit from the left (input_value_left). */
double input_value(const input_table *tab, size_t col, double t);
double input_value_left(const input_table *tab, size_t col, double t);
/* Discrete inputs: the value of the last sample at or before t (input_value_held), or before t. */
double input_value_held(const input_table *tab, size_t col, double t);
double input_value_held_left(const input_table *tab, size_t col, double t);
/* Does the column's value jump at t (held: as a discrete input)? */
int input_steps_at(const input_table *tab, size_t col, double t, int held);
void input_free(input_table *tab);

#endif
