/* Lagrangian model options: one-way coupling, transport only, first-order
 * scheme, no turbulent dispersion, no Brownian motion, no deposition
 * model, no statistics -> fully deterministic trajectories.              */

#include "cs_defs.h"
#include <math.h>
#include <stdio.h>
#include "cs_headers.h"
#include "cswm_common.h"

BEGIN_C_DECLS

void
cs_user_lagr_model(void)
{
  cs_glob_lagr_time_scheme->iilagr = CS_LAGR_ONEWAY_COUPLING;
  cs_glob_lagr_time_scheme->isuila = 0;          /* no Lagrangian restart */
  cs_glob_lagr_time_scheme->isttio = 0;          /* unsteady carrier phase */
  cs_glob_lagr_time_scheme->t_order = 1;         /* 1st-order SDE scheme */
  cs_glob_lagr_time_scheme->idistu = 0;          /* no turbulent dispersion */
  cs_glob_lagr_time_scheme->idiffl = 0;
  cs_glob_lagr_time_scheme->modcpl = 0;
  cs_glob_lagr_time_scheme->ilapoi = 0;          /* no Poisson correction */

  cs_glob_lagr_model->physical_model = 0;        /* transport only */
  cs_glob_lagr_model->deposition = 0;
  cs_glob_lagr_model->resuspension = 0;
  cs_glob_lagr_model->roughness = 0;
  cs_glob_lagr_model->clogging = 0;
  cs_glob_lagr_model->dlvo = 0;
  cs_glob_lagr_model->n_stat_classes = 0;
  cs_glob_lagr_brownian->lamvbr = 0;

  /* one user particle variable: packed (particle id, collision count),
     see cswm_common.h (do NOT use more than 1 in 6.0.2) */
  cs_lagr_set_n_user_variables(1);
}

END_C_DECLS
