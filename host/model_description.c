/* modelDescription.xml reader (libxml2). Only what a Model-Exchange host uses is kept. */
#include "model_description.h"

#include <libxml/parser.h>
#include <libxml/tree.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <errno.h>
#include <limits.h>
#include <math.h>
#include <sys/stat.h>
#include <unistd.h>

#include "fmu_archive.h"

static char *attr(xmlNode *node, const char *name)
{
    xmlChar *v = xmlGetProp(node, (const xmlChar *)name);
    char *copy;
    if (!v) return NULL;
    copy = strdup((const char *)v);
    xmlFree(v);
    return copy;
}

static xmlNode *child(xmlNode *node, const char *name)
{
    for (xmlNode *c = node ? node->children : NULL; c; c = c->next)
        if (c->type == XML_ELEMENT_NODE && strcmp((const char *)c->name, name) == 0) return c;
    return NULL;
}

static int count_children(xmlNode *node, const char *name)
{
    int n = 0;
    for (xmlNode *c = node ? node->children : NULL; c; c = c->next)
        if (c->type == XML_ELEMENT_NODE && strcmp((const char *)c->name, name) == 0) n++;
    return n;
}

static int read_double(xmlNode *node, const char *name, double *out)
{
    char *v = attr(node, name), *end;
    int ok = 0;
    if (v) {
        *out = strtod(v, &end);
        ok = end != v && *end == '\0';
        free(v);
    }
    return ok;
}

/* A whole decimal number without sign or spaces, at most max: 0; else -1. strtoul alone takes
 * "-1", " 7" and wraps 4294967326 to 30. */
static int parse_count(const char *text, unsigned long long max, unsigned long long *out)
{
    unsigned long long v = 0;
    if (!text || !*text) return -1;
    for (const char *p = text; *p; p++) {
        if (*p < '0' || *p > '9') return -1;
        if (v > (max - (unsigned long long)(*p - '0')) / 10) return -1;
        v = 10 * v + (unsigned long long)(*p - '0');
    }
    *out = v;
    return 0;
}

/* An optional finite Real attribute: 1 read, 0 absent, -1 present but not a finite number. */
static int read_finite(xmlNode *node, const char *name, double *out)
{
    char *v = attr(node, name);
    int ok;
    if (!v) return 0;
    free(v);
    ok = read_double(node, name, out) && isfinite(*out);
    return ok ? 1 : -1;
}

/* FMI 2.0 requires the modelIdentifier to be a C identifier: it also names the binary, so a '/'
 * or ".." in it would point outside the FMU. */
static int is_c_identifier(const char *s)
{
    if (!*s || !(s[0] == '_' || (s[0] >= 'A' && s[0] <= 'Z') || (s[0] >= 'a' && s[0] <= 'z'))) return 0;
    for (const char *p = s; *p; p++)
        if (!(*p == '_' || (*p >= 'A' && *p <= 'Z') || (*p >= 'a' && *p <= 'z') || (*p >= '0' && *p <= '9'))) return 0;
    return strlen(s) <= 200;
}

const char *md_type_name(md_type t)
{
    static const char *names[] = {"Real", "Integer", "Boolean", "String", "Enumeration"};
    return names[t];
}

static int parse_variable(xmlNode *sv, md_variable *v, char *err, size_t n)
{
    static const char *types[] = {"Real", "Integer", "Boolean", "String", "Enumeration"};
    char *vr = attr(sv, "valueReference");
    unsigned long long number;
    xmlNode *typed = NULL;
    memset(v, 0, sizeof *v);
    v->line = sv->line;
    v->name = attr(sv, "name");
    if (!v->name || !vr) {
        snprintf(err, n, "line %d: ScalarVariable without name or valueReference", sv->line);
        free(vr);
        return -1;
    }
    if (parse_count(vr, 4294967295ULL, &number) != 0) {
        snprintf(err, n, "line %d: variable '%s' has valueReference '%s' (expected an integer in [0, 4294967295])",
                 sv->line, v->name, vr);
        free(vr);
        return -1;
    }
    v->vr = (unsigned int)number;
    free(vr);
    v->causality = attr(sv, "causality");
    if (!v->causality) v->causality = strdup("local");
    v->variability = attr(sv, "variability");
    if (!v->variability) v->variability = strdup("continuous");
    v->initial = attr(sv, "initial");
    for (int t = 0; t < 5 && !typed; t++)
        if ((typed = child(sv, types[t]))) v->type = (md_type)t;
    if (!typed) {
        snprintf(err, n, "line %d: variable '%s' has no type element", sv->line, v->name);
        return -1;
    }
    v->start = attr(typed, "start");
    v->nominal = 1.0;
    if (v->type == MD_REAL && (read_finite(typed, "nominal", &v->nominal) < 0 || !(v->nominal > 0))) {
        snprintf(err, n, "line %d: variable '%s' has a nominal that is not a finite number > 0", typed->line, v->name);
        return -1;
    }
    if (v->type == MD_REAL && (v->derivative_of = attr(typed, "derivative")) != NULL &&
        (parse_count(v->derivative_of, UINT_MAX, &number) != 0 || number == 0)) {
        snprintf(err, n, "line %d: variable '%s' has derivative '%s' (expected an index >= 1)", typed->line, v->name,
                 v->derivative_of);
        return -1;
    }
    return 0;
}

/* The file into memory, refusing more than FMU_MD_MAX_BYTES and any DOCTYPE: an FMI model
 * description needs no DTD, and entity declarations are how a small file makes the parser
 * expand gigabytes (or read other files). */
static char *read_md_file(const char *path, long *len, char *err, size_t n)
{
    FILE *f;
    struct stat st;
    char *buf;
    if (access(path, R_OK) != 0 || stat(path, &st) != 0) {
        snprintf(err, n, "%s: %s (an FMU must contain modelDescription.xml)", path, strerror(errno));
        return NULL;
    }
    if (!S_ISREG(st.st_mode) || st.st_size > FMU_MD_MAX_BYTES) {
        snprintf(err, n, "%s: not a regular file of at most %ld MiB", path, FMU_MD_MAX_BYTES >> 20);
        return NULL;
    }
    if (!(f = fopen(path, "rb"))) { snprintf(err, n, "%s: %s", path, strerror(errno)); return NULL; }
    buf = malloc((size_t)st.st_size + 1);
    *len = buf ? (long)fread(buf, 1, (size_t)st.st_size, f) : 0;
    if (!buf || ferror(f) || *len != (long)st.st_size) {
        snprintf(err, n, "%s: %s", path, buf ? "read error" : "out of memory");
        free(buf);
        fclose(f);
        return NULL;
    }
    fclose(f);
    buf[*len] = '\0';
    /* memmem, not strstr: a NUL byte must not hide what follows it */
    const char *at = memmem(buf, (size_t)*len, "<!DOCTYPE", 9);
    if (!at) at = memmem(buf, (size_t)*len, "<!ENTITY", 8);
    if (at) {
        long line = 1;
        for (const char *p = buf; p < at; p++) line += *p == '\n';
        snprintf(err, n, "%s:%ld: a DOCTYPE or entity declaration is not allowed in a model description", path, line);
        free(buf);
        return NULL;
    }
    return buf;
}

static xmlDoc *parse_xml(const char *path, char *err, size_t n)
{
    long len;
    char *buf = read_md_file(path, &len, err, n);
    xmlDoc *doc;
    if (!buf) return NULL;
    doc = xmlReadMemory(buf, (int)len, path, NULL, XML_PARSE_NONET | XML_PARSE_NOERROR | XML_PARSE_NOWARNING);
    free(buf);
    if (!doc) {
        const xmlError *e = xmlGetLastError();
        size_t l;
        snprintf(err, n, "%s:%d: not well-formed XML: %s", path, e ? e->line : 0,
                 e && e->message ? e->message : "parse error");
        l = strlen(err); /* libxml2 ends its messages with a newline; ours are one line */
        while (l > 0 && (err[l - 1] == '\n' || err[l - 1] == '\r')) err[--l] = '\0';
    }
    return doc;
}

/* numberOfEventIndicators: absent (0) or a whole number within MD_MAX_EVENT_INDICATORS. */
static int read_event_indicators(const char *path, xmlNode *root, model_description *md, char *err, size_t n)
{
    char *v = attr(root, "numberOfEventIndicators");
    unsigned long long k = 0;
    int bad = v && parse_count(v, ULLONG_MAX, &k) != 0;
    if (bad || k > MD_MAX_EVENT_INDICATORS) {
        snprintf(err, n, "%s:%d: numberOfEventIndicators '%s' is not a whole number in [0, %d]", path, root->line, v,
                 MD_MAX_EVENT_INDICATORS);
        free(v);
        return -1;
    }
    free(v);
    md->n_event_indicators = (int)k;
    return 0;
}

static int read_default_experiment(const char *path, xmlNode *root, model_description *md, char *err, size_t n)
{
    xmlNode *de = child(root, "DefaultExperiment");
    int start = de ? read_finite(de, "startTime", &md->start_time) : 0;
    int stop = de ? read_finite(de, "stopTime", &md->stop_time) : 0;
    if (start < 0 || stop < 0) {
        snprintf(err, n, "%s:%d: DefaultExperiment %s is not a finite number", path, de->line, start < 0 ? "startTime" : "stopTime");
        return -1;
    }
    md->has_start_time = start;
    md->has_stop_time = stop;
    return 0;
}

static int read_variables(const char *path, xmlNode *root, model_description *md, char *err, size_t n)
{
    xmlNode *vars = child(root, "ModelVariables");
    size_t i = 0;
    char why[1024];
    md->n_vars = (size_t)count_children(vars, "ScalarVariable");
    md->vars = calloc(md->n_vars ? md->n_vars : 1, sizeof *md->vars);
    if (!md->vars) { md->n_vars = 0; snprintf(err, n, "%s: out of memory", path); return -1; }
    for (xmlNode *c = vars ? vars->children : NULL; c; c = c->next) {
        if (c->type != XML_ELEMENT_NODE || strcmp((const char *)c->name, "ScalarVariable") != 0) continue;
        if (parse_variable(c, &md->vars[i++], why, sizeof why) != 0) {
            md->n_vars = i;
            snprintf(err, n, "%s:%s", path, why + 5); /* "line N: ..." as "PATH:N: ..." */
            return -1;
        }
    }
    return 0;
}

static int by_name(const void *a, const void *b)
{
    const md_variable *x = *(const md_variable *const *)a, *y = *(const md_variable *const *)b;
    const int c = strcmp(x->name, y->name);
    return c ? c : (x->line > y->line) - (x->line < y->line);
}

/* FMI 2.0: variable names are unique. Two variables of one name would both be written under it
 * (a CSV header "time,s1,s1") and --set would reach only the first. Sorted, so that a hostile
 * file of a million variables is checked in n log n. */
static int check_unique_names(const char *path, const model_description *md, char *err, size_t n)
{
    const md_variable **sorted = calloc(md->n_vars + 1, sizeof *sorted);
    int rc = 0;
    if (!sorted) { snprintf(err, n, "%s: out of memory", path); return -1; }
    for (size_t i = 0; i < md->n_vars; i++) sorted[i] = &md->vars[i];
    qsort(sorted, md->n_vars, sizeof *sorted, by_name);
    for (size_t i = 1; i < md->n_vars && rc == 0; i++)
        if (strcmp(sorted[i - 1]->name, sorted[i]->name) == 0) {
            snprintf(err, n, "%s:%d: variable '%s' is declared twice (also on line %d): names must be unique", path,
                     sorted[i]->line, sorted[i]->name, sorted[i - 1]->line);
            rc = -1;
        }
    free(sorted);
    return rc;
}

/* ModelStructure/Derivatives: each Unknown is the 1-based index of a Real variable with a
 * derivative attribute naming a Real state, and every such variable is listed (so a missing
 * <Derivatives> cannot silently freeze the states). */
static int read_derivatives(const char *path, xmlNode *root, model_description *md, char *err, size_t n)
{
    xmlNode *der = child(child(root, "ModelStructure"), "Derivatives");
    size_t with_attr = 0;
    for (size_t i = 0; i < md->n_vars; i++) with_attr += md->vars[i].derivative_of != NULL;
    md->n_states = count_children(der, "Unknown");
    for (xmlNode *c = der ? der->children : NULL; c; c = c->next) {
        char *ix;
        unsigned long long k = 0;
        int bad;
        if (c->type != XML_ELEMENT_NODE || strcmp((const char *)c->name, "Unknown") != 0) continue;
        ix = attr(c, "index");
        bad = parse_count(ix, md->n_vars, &k) != 0 || k == 0;
        if (!bad) {
            const md_variable *d = &md->vars[k - 1];
            unsigned long long s = 0;
            bad = d->type != MD_REAL || !d->derivative_of || parse_count(d->derivative_of, md->n_vars, &s) != 0 ||
                  s == 0 || md->vars[s - 1].type != MD_REAL;
        }
        if (bad) {
            snprintf(err, n, "%s:%d: Derivatives Unknown index '%s' is not the index (1 to %zu) of a Real variable "
                     "whose derivative attribute names a Real state", path, c->line, ix ? ix : "(missing)", md->n_vars);
            free(ix);
            return -1;
        }
        free(ix);
    }
    if ((size_t)md->n_states != with_attr) {
        snprintf(err, n, "%s: ModelStructure lists %d Derivatives, but %zu variables have a derivative attribute", path,
                 md->n_states, with_attr);
        return -1;
    }
    return 0;
}

/* ModelStructure/Outputs: the 1-based indices of exactly the variables with causality "output"
 * (fmi2sim writes those; a description that disagrees with itself is corrupt). */
static int read_outputs(const char *path, xmlNode *root, const model_description *md, char *err, size_t n)
{
    xmlNode *outs = child(child(root, "ModelStructure"), "Outputs");
    size_t declared = 0, listed = 0;
    for (size_t i = 0; i < md->n_vars; i++) declared += strcmp(md->vars[i].causality, "output") == 0;
    for (xmlNode *c = outs ? outs->children : NULL; c; c = c->next) {
        char *ix;
        unsigned long long k = 0;
        if (c->type != XML_ELEMENT_NODE || strcmp((const char *)c->name, "Unknown") != 0) continue;
        ix = attr(c, "index");
        if (parse_count(ix, md->n_vars, &k) != 0 || k == 0 || strcmp(md->vars[k - 1].causality, "output") != 0) {
            snprintf(err, n, "%s:%d: Outputs Unknown index '%s' is not the index (1 to %zu) of a variable with "
                     "causality output", path, c->line, ix ? ix : "(missing)", md->n_vars);
            free(ix);
            return -1;
        }
        free(ix);
        listed++;
    }
    if (listed != declared) {
        snprintf(err, n, "%s: ModelStructure lists %zu Outputs, but %zu variables have causality output", path, listed, declared);
        return -1;
    }
    return 0;
}

static int read_model_exchange(const char *path, xmlNode *root, model_description *md, char *err, size_t n)
{
    xmlNode *me = child(root, "ModelExchange");
    char *v;
    if (!me) { snprintf(err, n, "%s: the FMU does not support Model Exchange", path); return -1; }
    md->model_identifier = attr(me, "modelIdentifier");
    if (!md->model_identifier) { snprintf(err, n, "%s:%d: ModelExchange has no modelIdentifier", path, me->line); return -1; }
    if (!is_c_identifier(md->model_identifier)) {
        snprintf(err, n, "%s:%d: modelIdentifier '%s' is not a C identifier (FMI 2.0 requires one; it names the binary)",
                 path, me->line, md->model_identifier);
        return -1;
    }
    v = attr(me, "completedIntegratorStepNotNeeded");
    md->needs_completed_integrator_step = !(v && strcmp(v, "true") == 0);
    free(v);
    return 0;
}

int md_parse(const char *path, model_description *md, char *err, size_t n)
{
    xmlDoc *doc;
    xmlNode *root;
    memset(md, 0, sizeof *md);
    if (!(doc = parse_xml(path, err, n))) return -1;
    root = xmlDocGetRootElement(doc);
    if (!root || strcmp((const char *)root->name, "fmiModelDescription") != 0) {
        snprintf(err, n, "%s: root element is not fmiModelDescription", path);
        xmlFreeDoc(doc);
        return -1;
    }
    md->fmi_version = attr(root, "fmiVersion");
    md->model_name = attr(root, "modelName");
    md->guid = attr(root, "guid");
    if (!md->fmi_version || strcmp(md->fmi_version, "2.0") != 0) {
        snprintf(err, n, "%s: fmiVersion is '%s', fmi2sim runs FMI 2.0 only", path,
                 md->fmi_version ? md->fmi_version : "(missing)");
        goto fail;
    }
    if (!md->guid) { snprintf(err, n, "%s: no guid attribute", path); goto fail; }
    if (read_model_exchange(path, root, md, err, n) != 0 || read_event_indicators(path, root, md, err, n) != 0 ||
        read_default_experiment(path, root, md, err, n) != 0 || read_variables(path, root, md, err, n) != 0 ||
        check_unique_names(path, md, err, n) != 0 || read_derivatives(path, root, md, err, n) != 0 || read_outputs(path, root, md, err, n) != 0)
        goto fail;
    xmlFreeDoc(doc);
    return 0;
fail:
    xmlFreeDoc(doc);
    return -1;
}

void md_free(model_description *md)
{
    for (size_t i = 0; i < md->n_vars; i++) {
        md_variable *v = &md->vars[i];
        free(v->name); free(v->causality); free(v->variability); free(v->initial); free(v->start);
        free(v->derivative_of);
    }
    free(md->vars);
    free(md->fmi_version); free(md->model_name); free(md->guid); free(md->model_identifier);
    memset(md, 0, sizeof *md);
}

const md_variable *md_find(const model_description *md, const char *name)
{
    for (size_t i = 0; i < md->n_vars; i++)
        if (strcmp(md->vars[i].name, name) == 0) return &md->vars[i];
    return NULL;
}
