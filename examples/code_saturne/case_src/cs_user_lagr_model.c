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
  cswm_lagr_transport_only();                   /* cswm_common.h */
}

END_C_DECLS
