/* The carrier phase of the pipe-flow study: air, k-epsilon RANS with wall functions, gravity
 * -y, constant time step; and the run's phase and length from pipe.params.               */
#include "cs_defs.h"

#include <stdio.h>

#include "cs_headers.h"
#include "pipe_params.h"

BEGIN_C_DECLS

void
cs_user_model(void)
{
  cs_turb_model_t *turb_model = cs_get_glob_turb_model();
  turb_model->iturb = CS_TURB_K_EPSILON_LIN_PROD;  /* k-epsilon, linear production */
}

void
cs_user_parameters(cs_domain_t  *domain)
{
  const pipe_params_t *pp = pipe_params();

  cs_time_step_options_t *time_opt = cs_get_glob_time_step_options();
  time_opt->idtvar = 0;                            /* constant, uniform time step */
  domain->time_step->dt_ref = pp->dt;
  /* nt_max is absolute: a restarted run continues from the checkpoint's step */
  cs_time_step_define_nt_max(pp->nt);

  cs_fluid_properties_t *fp = cs_get_glob_fluid_properties();
  fp->ro0 = 1.205;                                 /* air at 20 C */
  fp->viscl0 = 1.82e-5;

  cs_physical_constants_t *pc = cs_get_glob_physical_constants();
  pc->gravity[0] = 0.; pc->gravity[1] = -9.81; pc->gravity[2] = 0.;

  cs_turb_ref_values_t *tr = cs_get_glob_turb_ref_values();
  tr->uref = pp->u_bulk;                           /* initial k, epsilon from these */
  tr->almax = pp->diameter_pipe;
}

END_C_DECLS
