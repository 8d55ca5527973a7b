/* The injection run (phase 1) puts n_particles glass beads, uniformly in volume, into
 * the whole pipe section at the local fluid velocity (code_saturne's own volume injection,
 * on one rank). The particle runs (phase 2) inject nothing: they restart from these.     */
#include "cs_defs.h"

#include "cs_headers.h"
#include "pipe_params.h"

BEGIN_C_DECLS

void
cs_user_lagr_volume_conditions(void)
{
  const pipe_params_t *pp = pipe_params();
  if (pp->phase != 1)
    return;
  cs_lagr_zone_data_t *lagr_vol_conds = cs_lagr_get_volume_conditions();
  const cs_zone_t *z = cs_volume_zone_by_id(0);     /* all cells */
  cs_lagr_injection_set_t *zis = cs_lagr_get_injection_set(lagr_vol_conds, z->id, 0);
  zis->n_inject = (cs_gnum_t)pp->n_particles;
  zis->injection_frequency = 0;                     /* at the first step only */
  zis->velocity_profile = -1;                       /* the fluid's velocity */
  zis->stat_weight = 1.0;
  zis->flow_rate = 0.0;
  zis->diameter = pp->d_p;
  zis->diameter_variance = 0.0;
  zis->density = pp->rho_p;
}

END_C_DECLS
