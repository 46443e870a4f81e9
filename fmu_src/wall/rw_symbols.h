/* The external symbols of RockingWall's physics (rw_parameters.c, rw_hinge_laws.c, rw_dynamics.c,
 * rw_indicators.c, rw_outputs.c, rw_events.c), its engine's API (rw_engine.h) and exact step (cs_exact.c) under
 * FMI2_FUNCTION_PREFIX (see fmu_symbol.h); the engine's internal functions have theirs in rw_engine_internal.h.
 * A new external function of the physics needs a line here: the test combined_fmus_symbols lists any symbol
 * without the prefix. */
#ifndef RW_SYMBOLS_H
#define RW_SYMBOLS_H

#include "fmu_symbol.h"

#define RW_NUMBER_OF_PARAMETERS FMU_SYMBOL(RW_NUMBER_OF_PARAMETERS)
#define RW_PARAM_INFO FMU_SYMBOL(RW_PARAM_INFO)
#define rw_F_base FMU_SYMBOL(rw_F_base)
#define rw_F_top FMU_SYMBOL(rw_F_top)
#define rw_caps FMU_SYMBOL(rw_caps)
#define rw_closed_forces FMU_SYMBOL(rw_closed_forces)
#define rw_closed_hinge_mask FMU_SYMBOL(rw_closed_hinge_mask)
#define rw_closed_force_form FMU_SYMBOL(rw_closed_force_form)
#define rw_collapse_G FMU_SYMBOL(rw_collapse_G)
#define rw_collapse_G_of FMU_SYMBOL(rw_collapse_G_of)
#define rw_collapse_reason FMU_SYMBOL(rw_collapse_reason)
#define rw_condition FMU_SYMBOL(rw_condition)
#define rw_derivatives FMU_SYMBOL(rw_derivatives)
#define rw_derive FMU_SYMBOL(rw_derive)
#define rw_energy FMU_SYMBOL(rw_energy)
#define rw_engine_free FMU_SYMBOL(rw_engine_free)
#define rw_engine_init FMU_SYMBOL(rw_engine_init)
#define rw_engine_new FMU_SYMBOL(rw_engine_new)
#define rw_engine_region_motion FMU_SYMBOL(rw_engine_region_motion)
#define rw_engine_run FMU_SYMBOL(rw_engine_run)
#define rw_engine_run_many FMU_SYMBOL(rw_engine_run_many)
#define rw_engine_size FMU_SYMBOL(rw_engine_size)
#define rw_engine_step FMU_SYMBOL(rw_engine_step)
#define rw_engine_track_dissipated FMU_SYMBOL(rw_engine_track_dissipated)
#define rw_event_indicators FMU_SYMBOL(rw_event_indicators)
#define rw_event_indicators_some FMU_SYMBOL(rw_event_indicators_some)
#define rw_event_indicator_rates FMU_SYMBOL(rw_event_indicator_rates)
#define rw_indicator_lines FMU_SYMBOL(rw_indicator_lines)
#define rw_collapse_form_of FMU_SYMBOL(rw_collapse_form_of)
#define rw_event_update FMU_SYMBOL(rw_event_update)
#define rw_exact_step FMU_SYMBOL(rw_exact_step)
#define rw_force_1dof FMU_SYMBOL(rw_force_1dof)
#define rw_force_1dof_affine FMU_SYMBOL(rw_force_1dof_affine)
#define rw_ground_power FMU_SYMBOL(rw_ground_power)
#define rw_hinge_Q FMU_SYMBOL(rw_hinge_Q)
#define rw_hinge_law_of FMU_SYMBOL(rw_hinge_law_of)
#define rw_init_regime FMU_SYMBOL(rw_init_regime)
#define rw_is_rigid FMU_SYMBOL(rw_is_rigid)
#define rw_mid_switch_is_bookkeeping FMU_SYMBOL(rw_mid_switch_is_bookkeeping)
#define rw_moments_of_q_alone FMU_SYMBOL(rw_moments_of_q_alone)
#define rw_open_hinges FMU_SYMBOL(rw_open_hinges)
#define rw_param_by_name FMU_SYMBOL(rw_param_by_name)
#define rw_param_by_vr FMU_SYMBOL(rw_param_by_vr)
#define rw_param_check FMU_SYMBOL(rw_param_check)
#define rw_param_get FMU_SYMBOL(rw_param_get)
#define rw_param_set FMU_SYMBOL(rw_param_set)
#define rw_params_default FMU_SYMBOL(rw_params_default)
#define rw_params_validate FMU_SYMBOL(rw_params_validate)
#define rw_s1 FMU_SYMBOL(rw_s1)
#define rw_s2 FMU_SYMBOL(rw_s2)
#define rw_sync_mid_side FMU_SYMBOL(rw_sync_mid_side)
#define rw_wall_statics FMU_SYMBOL(rw_wall_statics)

#endif
