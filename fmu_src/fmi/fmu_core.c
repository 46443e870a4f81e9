/* The parts of the FMI layers that do not depend on the FMI version: see fmu_core.h. */
#include "fmu_core.h"

#include <stdio.h>
#include <string.h>

/* ---- default model callbacks: a model writes only what it has ------------------------------ */

static void no_get_integer(void *M, int initializing, const unsigned vr[], size_t n, int v[])
{
    (void)M; (void)initializing; (void)vr;
    memset(v, 0, n * sizeof *v); /* unreachable: there is no Integer variable to look up */
}

static void no_get_boolean(void *M, const unsigned vr[], size_t n, int v[])
{
    (void)M; (void)vr;
    memset(v, 0, n * sizeof *v); /* unreachable: there is no Boolean variable to look up */
}

static int no_set_real(void *M, unsigned vr, double v, char *msg, size_t n)
{
    (void)M; (void)v;
    snprintf(msg, n, "value reference %u cannot be set", vr);
    return 1;
}

static int no_set_integer(void *M, unsigned vr, int v, char *msg, size_t n)
{
    (void)M; (void)v;
    snprintf(msg, n, "value reference %u cannot be set", vr);
    return 1;
}

static int no_checks_at_exit_init(void *M, double time, const fmu_logger *log, char *msg, size_t n)
{
    (void)M; (void)time; (void)log; (void)msg; (void)n;
    return 0;
}

static void no_event_indicators(void *M, int initializing, double z[]) { (void)M; (void)initializing; (void)z; }

static void keep_nominals(double x[]) { (void)x; } /* the caller filled in 1 for every state */

static void no_events(void *M, double time, const fmu_logger *log, fmu_event_result *r)
{
    (void)M; (void)time; (void)log;
    memset(r, 0, sizeof *r);
}

void fmu_model_with_defaults(fmu_model *m)
{
    *m = FMU_MODEL;
    if (m->data_tail_size) m->data_size += m->data_tail_size(); /* one block of data, one byte copy */
    if (!m->get_integer) m->get_integer = no_get_integer;
    if (!m->get_boolean) m->get_boolean = no_get_boolean;
    if (!m->set_real) m->set_real = no_set_real;
    if (!m->set_integer) m->set_integer = no_set_integer;
    if (!m->exit_init) m->exit_init = no_checks_at_exit_init;
    if (!m->event_indicators) m->event_indicators = no_event_indicators;
    if (!m->nominals) m->nominals = keep_nominals;
    if (!m->event_update) m->event_update = no_events;
}

/* ---- variables ----------------------------------------------------------------------------- */

const fmu_var *fmu_find_var(const fmu_model *m, unsigned vr)
{
    size_t i;
    for (i = 0; i < m->nvars; i++)
        if (m->vars[i].vr == vr) return &m->vars[i];
    return NULL;
}

int fmu_var_kind(const fmu_var *v)
{
    if (!strcmp(v->causality, "input")) return FMU_SET_ALWAYS;
    if (!strcmp(v->causality, "parameter") || !strcmp(v->initial, "exact")) return FMU_SET_BEFORE_INIT_END;
    return FMU_SET_NEVER;
}

void fmu_core_inputs(fmu_core *core)
{
    size_t i;
    core->n_inputs = 0;
    for (i = 0; i < core->model.nvars; i++)
        if (core->model.vars[i].type == FMU_REAL && fmu_var_kind(&core->model.vars[i]) == FMU_SET_ALWAYS)
            core->inputs[core->n_inputs++].vr = core->model.vars[i].vr;
}

cs_input *fmu_core_find_input(fmu_core *core, unsigned vr)
{
    size_t k;
    for (k = 0; k < core->n_inputs; k++)
        if (core->inputs[k].vr == vr) return &core->inputs[k];
    return NULL;
}

void fmu_core_nominals(const fmu_core *core, double x[])
{
    int i;
    for (i = 0; i < core->model.nx; i++) x[i] = 1.0;
    core->model.nominals(x);
}

/* ---- Co-Simulation step -------------------------------------------------------------------- */

/* the values the master set, read back from the model, as the held values over the next step */
static void refresh_inputs(fmu_core *core)
{
    size_t k;
    for (k = 0; k < core->n_inputs; k++)
        core->model.get_real(core->M, 0, core->time, &core->inputs[k].vr, 1, &core->inputs[k].value);
}

/* the model's exact step over the inputs' slopes, or FMU_NOT_EXACT */
/* The inputs of a step as exact_step takes them. A fixed bound, not a variable-length array: MSVC,
 * which importers use to build FMUs from their sources, has none. */
#define FMU_MAX_STEP_INPUTS 32

static int exact_step(fmu_core *core, double h, const fmu_logger *log, double *t_reached, char *msg, size_t msg_n)
{
    unsigned vr[FMU_MAX_STEP_INPUTS];
    double slope[FMU_MAX_STEP_INPUTS];
    size_t k;
    if (!core->model.exact_step) return FMU_NOT_EXACT;
    if (core->n_inputs > FMU_MAX_STEP_INPUTS) {
        snprintf(msg, msg_n, "%zu inputs, more than the %d an exact step takes", core->n_inputs, FMU_MAX_STEP_INPUTS);
        return -1;
    }
    for (k = 0; k < core->n_inputs; k++) vr[k] = core->inputs[k].vr, slope[k] = core->inputs[k].slope;
    return core->model.exact_step(core->M, core->time, h, vr, slope, core->n_inputs, log, t_reached, msg, msg_n);
}

int fmu_core_step(fmu_core *core, double h, const fmu_logger *log, char *msg, size_t msg_n)
{
    double t_reached = core->time;
    size_t k;
    int rc;
    refresh_inputs(core);
    msg[0] = '\0'; /* the exact step may leave its reason for declining here (cs_without_cvode.c reports it) */
    rc = exact_step(core, h, log, &t_reached, msg, msg_n); /* RockingWall, Diaphragm: closed-form steps */
    if (rc == FMU_NOT_EXACT) rc = cs_step(core->cs, core->time, h, core->inputs, core->n_inputs, log, &t_reached, msg, msg_n);
    for (k = 0; k < core->n_inputs; k++) core->inputs[k].slope = 0.0; /* derivatives hold for one step */
    if (rc < 0) return -1;
    core->time = t_reached;
    core->last_successful_time = t_reached;
    if (rc == 1) core->terminated = 1;
    return rc == 1 ? 1 : 0;
}

/* ---- FMU state ----------------------------------------------------------------------------- */

#define STATE_MAGIC "RWFMUS1" /* 8 bytes with the terminating zero; the last digit is the format */

typedef struct {
    char magic[8];
    char guid[64];
    unsigned long long size; /* of the whole block */
    int co_simulation;
    int initialized;         /* taken after initialization mode was left */
    int terminated;
    double time, rtol, last_successful_time;
    unsigned long long data_size, n_inputs, solver_size;
} state_header;

static size_t size_of(const state_header *h)
{
    return sizeof *h + (size_t)h->data_size + (size_t)h->n_inputs * sizeof(double) + (size_t)h->solver_size;
}

static void make_header(const fmu_core *core, state_header *h)
{
    memset(h, 0, sizeof *h);
    memcpy(h->magic, STATE_MAGIC, sizeof h->magic);
    snprintf(h->guid, sizeof h->guid, "%s", core->model.guid);
    h->co_simulation = core->co_simulation;
    h->initialized = core->initialized;
    h->terminated = core->terminated;
    h->time = core->time;
    h->rtol = core->rtol;
    h->last_successful_time = core->last_successful_time;
    h->data_size = core->model.data_size;
    h->n_inputs = core->n_inputs;
    h->solver_size = core->cs ? cs_state_size(core->cs) : 0;
    h->size = size_of(h);
}

size_t fmu_state_size(const fmu_core *core)
{
    state_header h;
    make_header(core, &h);
    return (size_t)h.size;
}

void fmu_state_write(const fmu_core *core, void *block)
{
    state_header h;
    unsigned char *p = (unsigned char *)block + sizeof h;
    size_t k;
    make_header(core, &h);
    memcpy(block, &h, sizeof h);
    memcpy(p, core->M, core->model.data_size);
    p += core->model.data_size;
    for (k = 0; k < core->n_inputs; k++, p += sizeof(double)) memcpy(p, &core->inputs[k].slope, sizeof(double));
    if (core->cs) cs_get_state(core->cs, p);
}

int fmu_state_is_ours(const void *block, char *msg, size_t msg_n)
{
    if (!block) return snprintf(msg, msg_n, "argument FMUstate must not be NULL"), 1;
    if (memcmp(block, STATE_MAGIC, sizeof STATE_MAGIC) != 0)
        return snprintf(msg, msg_n, "not an FMU state of this FMU (bad magic number)"), 1;
    return 0;
}

size_t fmu_state_bytes(const void *block)
{
    state_header h;
    memcpy(&h, block, sizeof h);
    return (size_t)h.size;
}

/* The GUID field of a block for a message: quoted when it is printable text, else the hex of its
 * first bytes (the block may be anything: its raw bytes must not reach a logger that decodes text). */
static void guid_as_text(const char guid[64], char *out, size_t n)
{
    const unsigned char *g = (const unsigned char *)guid;
    size_t k;
    for (k = 0; k < 64 && g[k] >= 0x20 && g[k] < 0x7f && g[k] != '%'; k++) continue;
    if (k > 0 && k < 64 && g[k] == '\0') {
        snprintf(out, n, "\"%.*s\"", (int)k, guid);
        return;
    }
    snprintf(out, n, "that is not text (its first bytes %02x %02x %02x %02x ...)", g[0], g[1], g[2], g[3]);
}

int fmu_state_check(const fmu_core *core, const void *block, size_t n, char *msg, size_t msg_n)
{
    state_header h, mine;
    char guid[80];
    if (n < sizeof h)
        return snprintf(msg, msg_n, "the FMU state has %u bytes, fewer than its header (%u)", (unsigned)n, (unsigned)sizeof h), 1;
    if (fmu_state_is_ours(block, msg, msg_n)) return 1;
    memcpy(&h, block, sizeof h);
    if (strncmp(h.guid, core->model.guid, sizeof h.guid) != 0) {
        guid_as_text(h.guid, guid, sizeof guid);
        return snprintf(msg, msg_n, "the FMU state belongs to the FMU with GUID %s, this FMU has GUID %s", guid,
                        core->model.guid), 1;
    }
    if (h.size != n) return snprintf(msg, msg_n, "the FMU state says it has %llu bytes, but %u were given", h.size, (unsigned)n), 1;
    make_header(core, &mine);
    if (h.data_size != mine.data_size || h.n_inputs != mine.n_inputs || size_of(&h) != n)
        return snprintf(msg, msg_n, "the FMU state's sizes (model data %llu, inputs %llu, total %llu) do not match this "
                                    "binary's (%llu, %llu)", h.data_size, h.n_inputs, h.size, mine.data_size, mine.n_inputs), 1;
    return 0;
}

/* Can the instance take this compatible state now (same interface type, same phase)? */
static int applicable(const fmu_core *core, const state_header *h, char *msg, size_t msg_n)
{
    state_header mine;
    make_header(core, &mine);
    if (h->co_simulation != mine.co_simulation)
        return snprintf(msg, msg_n, "the FMU state is of a %s instance, this is a %s instance",
                        h->co_simulation ? "Co-Simulation" : "Model Exchange",
                        mine.co_simulation ? "Co-Simulation" : "Model Exchange"), 1;
    if (h->initialized != mine.initialized)
        return snprintf(msg, msg_n, "the FMU state was taken %s ExitInitializationMode, the instance is %s it",
                        h->initialized ? "after" : "before", mine.initialized ? "past" : "before"), 1;
    if (h->solver_size != mine.solver_size)
        return snprintf(msg, msg_n, "the FMU state's integrator part has %llu bytes, expected %llu", h->solver_size,
                        mine.solver_size), 1;
    return 0;
}

int fmu_state_read(fmu_core *core, const void *block, char *msg, size_t msg_n)
{
    state_header h;
    const unsigned char *p = (const unsigned char *)block + sizeof h;
    size_t k;
    if (fmu_state_check(core, block, fmu_state_bytes(block), msg, msg_n)) return 1;
    memcpy(&h, block, sizeof h);
    if (applicable(core, &h, msg, msg_n)) return 1;
    if (core->cs && cs_set_state(core->cs, p + h.data_size + h.n_inputs * sizeof(double), (size_t)h.solver_size, msg, msg_n))
        return 1;
    memcpy(core->M, p, core->model.data_size);
    p += core->model.data_size;
    for (k = 0; k < core->n_inputs; k++, p += sizeof(double)) memcpy(&core->inputs[k].slope, p, sizeof(double));
    core->time = h.time;
    core->rtol = h.rtol;
    core->terminated = h.terminated;
    core->last_successful_time = h.last_successful_time;
    return 0;
}
