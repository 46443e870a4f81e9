/* modelDescription.xml reader (libxml2). Only what a Model-Exchange host uses is kept. */
#include "model_description.h"

#include <libxml/parser.h>
#include <libxml/tree.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <errno.h>
#include <unistd.h>

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

const char *md_type_name(md_type t)
{
    static const char *names[] = {"Real", "Integer", "Boolean", "String", "Enumeration"};
    return names[t];
}

static int parse_variable(xmlNode *sv, md_variable *v, char *err, size_t n)
{
    static const char *types[] = {"Real", "Integer", "Boolean", "String", "Enumeration"};
    char *vr = attr(sv, "valueReference"), *end = NULL;
    xmlNode *typed = NULL;
    memset(v, 0, sizeof *v);
    v->name = attr(sv, "name");
    if (!v->name || !vr) {
        snprintf(err, n, "line %d: ScalarVariable without name or valueReference", sv->line);
        free(vr);
        return -1;
    }
    v->vr = (unsigned int)strtoul(vr, &end, 10);
    if (end == vr || *end) {
        snprintf(err, n, "line %d: variable '%s' has valueReference '%s'", sv->line, v->name, vr);
        free(vr);
        return -1;
    }
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
    if (v->type == MD_REAL) read_double(typed, "nominal", &v->nominal);
    return 0;
}

int md_parse(const char *path, model_description *md, char *err, size_t n)
{
    xmlDoc *doc;
    xmlNode *root, *me, *vars, *ms;
    memset(md, 0, sizeof *md);
    if (access(path, R_OK) != 0) {
        snprintf(err, n, "%s: %s (an FMU must contain modelDescription.xml)", path, strerror(errno));
        return -1;
    }
    doc = xmlReadFile(path, NULL, XML_PARSE_NONET | XML_PARSE_NOERROR | XML_PARSE_NOWARNING);
    if (!doc) {
        const xmlError *e = xmlGetLastError();
        size_t len;
        snprintf(err, n, "%s:%d: not well-formed XML: %s", path, e ? e->line : 0,
                 e && e->message ? e->message : "parse error");
        len = strlen(err); /* libxml2 ends its messages with a newline; ours are one line */
        while (len > 0 && (err[len - 1] == '\n' || err[len - 1] == '\r')) err[--len] = '\0';
        return -1;
    }
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
    me = child(root, "ModelExchange");
    if (!me) { snprintf(err, n, "%s: the FMU does not support Model Exchange", path); goto fail; }
    md->model_identifier = attr(me, "modelIdentifier");
    if (!md->model_identifier) { snprintf(err, n, "%s: ModelExchange has no modelIdentifier", path); goto fail; }
    {
        char *v = attr(me, "completedIntegratorStepNotNeeded");
        md->needs_completed_integrator_step = !(v && strcmp(v, "true") == 0);
        free(v);
    }
    {
        char *v = attr(root, "numberOfEventIndicators");
        md->n_event_indicators = v ? atoi(v) : 0;
        free(v);
    }
    {
        xmlNode *de = child(root, "DefaultExperiment");
        if (de) {
            md->has_start_time = read_double(de, "startTime", &md->start_time);
            md->has_stop_time = read_double(de, "stopTime", &md->stop_time);
        }
    }
    vars = child(root, "ModelVariables");
    md->n_vars = (size_t)count_children(vars, "ScalarVariable");
    md->vars = calloc(md->n_vars ? md->n_vars : 1, sizeof *md->vars);
    {
        size_t i = 0;
        for (xmlNode *c = vars ? vars->children : NULL; c; c = c->next) {
            if (c->type != XML_ELEMENT_NODE || strcmp((const char *)c->name, "ScalarVariable") != 0) continue;
            if (parse_variable(c, &md->vars[i++], err, n) != 0) { md->n_vars = i; goto fail; }
        }
    }
    ms = child(root, "ModelStructure");
    md->n_states = count_children(child(ms, "Derivatives"), "Unknown");
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
