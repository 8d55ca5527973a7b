#ifndef PIPE_PARAMS_H
#define PIPE_PARAMS_H
/* The run parameters of the pipe-flow study, read at run time from the file `pipe.params` in
 * the run directory ("key value" lines, '#' comments), so that one compiled solver serves the
 * fluid run, the particle-injection run and every wall of the study (setup_pipe.sh and
 * run_pipe.sh write the file; docs/pipe-flow.md lists the keys).
 *
 * PINNED TO code_saturne 6.0.x like the rest of the hook.                                   */

#include <stdio.h>

typedef struct {
  int    phase;            /* 0 fluid (RANS only), 1 inject (one Lagrangian step), 2 particles */
  int    nt;               /* time steps of this run */
  double dt;               /* time step (s) */
  double diameter_pipe;    /* D (m) */
  double length;           /* L, the streamwise period (m) */
  double u_bulk;           /* target bulk velocity (m/s) */
  int    wall;             /* 0 smooth, 1 isotropic, 2 lay along the axis, 3 lay around the circumference */
  double delta_xi_deg;     /* roughness along the lay */
  double delta_zeta_deg;   /* roughness across the lay */
  int    model;            /* roughwall RW_MODEL_* */
  int    law;              /* roughwall RW_LAW_* */
  int    preset;           /* roughwall RW_PRESET_* */
  unsigned long long seed; /* the wall model's seed */
  int    n_particles;      /* particles injected (ids 0 ... n_particles - 1) */
  double d_p;              /* particle diameter (m) */
  double rho_p;            /* particle density (kg/m3) */
  int    dispersion;       /* code_saturne's turbulent dispersion on (1) or off (0) */
  double t_sample;         /* start of the sampling window, from the start of this run (s) */
  int    n_bins;           /* bins across a diameter */
  int    log_hits;         /* write every wall hit in the window to hits_rank<r>.csv */
  int    spin;             /* carry the particles' spin between hits (pipe_spin.h) */
  int    saffman;          /* Saffman-Mei shear lift (pipe_forces.h) */
  int    magnus;           /* Magnus lift (pipe_forces.h) */
  int    complete_langevin;/* code_saturne's complete dispersion model instead of the simplified
                              one (0 where dispersion is 0) */
  int    nt_restart;       /* the time step a particle run restarts from (the injection's last) */
  int    trace;            /* write the state of particles 0 ... trace-1 every step */
  double kick;             /* a test scene: the particles thrown at the wall at the end of the
                              run's first step, this radial speed (m/s) added */
  int    mesh_sides;       /* sides of the mesh's polygonal wall (for pipe-stats' areas; 0: unknown) */
} pipe_params_t;

/* The parameters, read once (aborts the run with a message naming the key on a bad line). */
const pipe_params_t *pipe_params(void);

/* Opens this rank's CSV file <stem>_rank<r>.csv in the run directory for writing and writes
   its header line (aborts the run if it cannot). */
FILE *pipe_rank_csv(const char *stem, const char *header);

#endif
