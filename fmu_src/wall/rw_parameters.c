/* RockingWall parameters: defaults, range checks, getters and setters, all from the one table
 * RW_PARAMETERS of rw_parameters.h. The rules that tie parameters together need the derived
 * quantities and are in rw_params_validate() (rw_dynamics.c). */
#include "rw_parameters.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#define RW_IS_INT_Real 0
#define RW_IS_INT_Integer 1
#define RW_PARAM_ROW(ID, VR, TYPE, UNIT, DEF, LO, HI, DESC) \
    {#ID, VR, RW_IS_INT_##TYPE, UNIT, DEF, LO, HI, offsetof(rw_params, ID), DESC},
const rw_param_info RW_PARAM_INFO[] = {RW_PARAMETERS(RW_PARAM_ROW)};
#undef RW_PARAM_ROW
const size_t RW_NUMBER_OF_PARAMETERS = sizeof RW_PARAM_INFO / sizeof RW_PARAM_INFO[0];

const rw_param_info *rw_param_by_name(const char *name)
{
    size_t i;
    for (i = 0; i < RW_NUMBER_OF_PARAMETERS; i++)
        if (!strcmp(RW_PARAM_INFO[i].name, name)) return &RW_PARAM_INFO[i];
    return NULL;
}

const rw_param_info *rw_param_by_vr(unsigned vr)
{
    size_t i;
    for (i = 0; i < RW_NUMBER_OF_PARAMETERS; i++)
        if (RW_PARAM_INFO[i].vr == vr) return &RW_PARAM_INFO[i];
    return NULL;
}

static void *field(rw_params *p, const rw_param_info *info)
{
    return (char *)p + info->offset;
}

double rw_param_get(const rw_params *p, const rw_param_info *info)
{
    const void *f = (const char *)p + info->offset;
    return info->is_integer ? (double)*(const int *)f : *(const double *)f;
}

static void store(rw_params *p, const rw_param_info *info, double value)
{
    if (info->is_integer) *(int *)field(p, info) = (int)value;
    else *(double *)field(p, info) = value;
}

void rw_params_default(rw_params *p)
{
    size_t i;
    memset(p, 0, sizeof *p);
    for (i = 0; i < RW_NUMBER_OF_PARAMETERS; i++) store(p, &RW_PARAM_INFO[i], RW_PARAM_INFO[i].def);
}

int rw_param_check(const rw_param_info *info, double v, char *msg, size_t n)
{
    const char *rule = NULL;
    if (!isfinite(v)) rule = "must be a finite number";
    else if (info->is_integer && v != floor(v)) rule = "must be a whole number";
    else if (!(v >= info->lo && v <= info->hi)) rule = "is out of range";
    if (!rule) return 0;
    snprintf(msg, n, "invalid parameter %s = %.17g: %s; allowed [%g, %g]%s%s (%s)", info->name, v, rule, info->lo,
             info->hi, *info->unit ? " " : "", info->unit, info->description);
    return 1;
}

int rw_param_set(rw_params *p, const rw_param_info *info, double value, char *msg, size_t n)
{
    if (rw_param_check(info, value, msg, n)) return 1;
    store(p, info, value);
    return 0;
}
