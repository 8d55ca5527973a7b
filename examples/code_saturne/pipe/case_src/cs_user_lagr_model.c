/* Lagrangian options of the pipe-flow study. The fluid run (phase 0) has no particles; the
 * injection run (phase 1) and the particle runs (phase 2) freeze the converged carrier phase
 * (one-way coupling on a frozen field), with code_saturne's own Langevin dispersion model on
 * or off (pipe.params `dispersion`). The particle runs restart from the injection run's
 * particles, so every wall of a study starts from the same particles, whatever the number
 * of MPI ranks. With pipe.params `complete_langevin` 1 the dispersion is code_saturne's
 * complete model instead of the simplified one. The lifts and the spin: pipe_forces.h.                                                                          */
#include "cs_defs.h"

#include "cs_headers.h"
#include "cswm_common.h"
#include "pipe_params.h"

BEGIN_C_DECLS

void
cs_user_lagr_model(void)
{
  const pipe_params_t *pp = pipe_params();
  if (pp->phase == 0) {
    cs_glob_lagr_time_scheme->iilagr = CS_LAGR_OFF;
    return;
  }
  cs_glob_lagr_time_scheme->iilagr = CS_LAGR_FROZEN_CONTINUOUS_PHASE;
  cs_glob_lagr_time_scheme->isuila = (pp->phase == 2);  /* particles from the injection run */
  cs_glob_lagr_time_scheme->isttio = 1;
  cs_glob_lagr_time_scheme->t_order = 1;
  cs_glob_lagr_time_scheme->idistu = pp->dispersion;    /* Langevin dispersion of the fluid seen */
  cswm_lagr_transport_only();                           /* ../case_src/cswm_common.h */
  /* no code_saturne statistics (the study keeps its own, pipe_tally.c): they would start
     after the last step, and a restart need not carry them */
  cs_glob_lagr_stat_options->isuist = 0;
  cs_glob_lagr_stat_options->idstnt = pp->nt + 1;
  cs_glob_lagr_stat_options->nstist = pp->nt + 1;
  if (pp->phase == 2 && pp->complete_langevin && pp->nt_restart <= 0)
    bft_error(__FILE__, __LINE__, 0, "pipe.params: complete_langevin needs nt_restart, "
              "the step the run restarts from (> 0)");
  if (pp->phase == 2 && pp->complete_langevin) {
    /* The complete model (Minier & Peirano 2001) needs the particles' mean velocity per cell:
       code_saturne's volume statistics, from the first step of this run (a run that does
       not read statistics must start them after its restart step: cs_lagr_lec.c, 6.0.2),
       accumulated over it (steady, isttio = 1). It applies from the step after modcpl on
       (cs_lagr_car.c), with the velocity gradient cs_user_lagr_ef gives it (pipe_forces.c).
       Where a cell has no statistics yet, code_saturne falls back to the particle's own
       velocities. */
    cs_glob_lagr_stat_options->idstnt = pp->nt_restart + 1;
    cs_glob_lagr_stat_options->nstist = pp->nt_restart + 1;
    cs_glob_lagr_time_scheme->modcpl = pp->nt_restart + 1;
    /* the mean flow along the pipe axis x (cs_lagr_car.c; the setup log prints this 1 as
       "y": cs_lagr_log.c indexes "xyz" from 0) */
    cs_glob_lagr_time_scheme->idirla = 1;
  }
}

END_C_DECLS
