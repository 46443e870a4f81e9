/* BuildingWithWalls: the instance data and its parameters (bw_params.c): where each parameter of
 * the variable table (bw_variables.h) lives, its range, its default, and the scene they make. */
#ifndef BW_PARAMS_H
#define BW_PARAMS_H

#include <stddef.h>

#include "fmu_model.h"
#include "rw_scene.h"

typedef struct {
    /* parameters: the walls' own (per storey) and the building's, as the scene takes them; the
     * damping ratios become the dashpots cs, cd when the scene is made */
    rw_scene_spec spec;
    rw_params shared; /* g, delta1Ratio, delta2A, delta2B, hingeSat, restRate of every wall */
    double zetad[RW_SCENE_MAX_STOREYS], zetas[RW_SCENE_MAX_STOREYS];
    double ag;   /* input */
    double x[2 + RW_SCENE_MAX_STOREYS * (RW_NX + BD_STATES_PER_FLOOR)]; /* the FMU's states (bw_variables.h) */
    rw_scene sc; /* the scene, from the end of initialization */
    int ready;
    double energy0, losses;
    const fmu_logger *log;
    double time;
} bw_data;

/* the table's defaults */
void bw_params_reset(bw_data *S);
/* where a Real / Integer parameter lives (NULL: vr is not one) */
double *bw_real_parameter(bw_data *S, unsigned vr);
int *bw_integer_parameter(bw_data *S, unsigned vr);
/* range check, then store: 0, or 1 with msg naming the parameter, the value and the range */
int bw_set_real_parameter(bw_data *S, unsigned vr, double value, char *msg, size_t n);
int bw_set_integer_parameter(bw_data *S, unsigned vr, int value, char *msg, size_t n);
/* the scene of the parameters: every wall flexibleTop with the shared parameters, the dashpots
 * from the damping ratios */
void bw_params_spec(const bw_data *S, rw_scene_spec *spec);

#endif
