/* The parts of an FMI 2.0 modelDescription.xml that a Model-Exchange host needs. */
#ifndef FMI2SIM_MODEL_DESCRIPTION_H
#define FMI2SIM_MODEL_DESCRIPTION_H

#include <stddef.h>

typedef enum { MD_REAL, MD_INTEGER, MD_BOOLEAN, MD_STRING, MD_ENUMERATION } md_type;

typedef struct {
    char *name;
    unsigned int vr;
    md_type type;
    char *causality;   /* "parameter", "input", "output", "local", ... (default "local") */
    char *variability; /* "constant", "fixed", "tunable", "discrete", "continuous" */
    char *initial;     /* may be NULL */
    char *start;       /* textual start value, may be NULL */
    double nominal;    /* Real: nominal attribute (finite, > 0) or 1 */
    char *derivative_of; /* Real: the derivative attribute (1-based index of its state), may be NULL */
    int line;          /* of its ScalarVariable in the file */
} md_variable;

/* More event indicators than this is no model but a corrupt or hostile file (CVODE allocates
 * several arrays of this length). */
#define MD_MAX_EVENT_INDICATORS 1000000

typedef struct {
    char *fmi_version, *model_name, *guid, *model_identifier;
    int n_states, n_event_indicators;
    int needs_completed_integrator_step;
    int has_start_time, has_stop_time;
    double start_time, stop_time;
    md_variable *vars;
    size_t n_vars;
} model_description;

/* Parse PATH; on failure return -1 with a message in err. */
int md_parse(const char *path, model_description *md, char *err, size_t n);
void md_free(model_description *md);
const md_variable *md_find(const model_description *md, const char *name);
const char *md_type_name(md_type t);

#endif
