/* Input signals: columns of samples in time, linearly interpolated, ends held. */
#ifndef FMI2SIM_INPUT_TABLE_H
#define FMI2SIM_INPUT_TABLE_H

#include <stddef.h>

typedef struct {
    char *name;      /* the FMU input variable it drives */
    double *values;  /* one per time sample */
} input_column;

typedef struct {
    char *source;    /* the file it was read from */
    double *t;       /* strictly increasing sample times */
    size_t n;        /* samples */
    input_column *cols;
    size_t ncols;
} input_table;

/* CSV: header "time,NAME,...", then numeric rows; errors name FILE:LINE. */
int input_read_csv(const char *path, input_table *tab, char *err, size_t n);
/* PEER NGA .AT2 (acceleration in g): one column named `name`, values * g * scale. */
int input_read_at2(const char *path, const char *name, double g, double scale, input_table *tab,
                   char *err, size_t n);
double input_value(const input_table *tab, size_t col, double t);
void input_free(input_table *tab);

#endif
