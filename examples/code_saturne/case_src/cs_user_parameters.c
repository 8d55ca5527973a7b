/* Fluid model and time stepping.
 * Laminar, constant-property air at rest (all fluid boundaries are walls,
 * see cs_user_boundary_conditions.f90), so the carrier phase stays at
 * rest (u = 0 to round-off) and particles move ballistically, slowed
 * only by a negligible drag (very heavy particles, see
 * cs_user_lagr_boundary_conditions.c). No gravity.                       */

#include "cs_defs.h"
#include <stdio.h>
#include "cs_headers.h"
#include "cswm_common.h"

BEGIN_C_DECLS

void
cs_user_model(void)
{
  cs_turb_model_t *turb_model = cs_get_glob_turb_model();
  turb_model->iturb = CS_TURB_NONE;     /* laminar */
}

void
cs_user_parameters(cs_domain_t  *domain)
{
  cs_time_step_options_t *time_opt = cs_get_glob_time_step_options();
  time_opt->idtvar = 0;                 /* constant, uniform time step */
  domain->time_step->dt_ref = CSWM_DT;
  domain->time_step->nt_max = CSWM_NT_MAX;

  cs_physical_constants_t *pc = cs_get_glob_physical_constants();
  pc->gravity[0] = 0.; pc->gravity[1] = 0.; pc->gravity[2] = 0.;
}

END_C_DECLS
