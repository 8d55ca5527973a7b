#ifndef PIPE_TALLY_H
#define PIPE_TALLY_H
/* Per-particle tallies of the pipe-flow study over the sampling window (pipe.params
 * t_sample to the end of the run), indexed by the particle's stable id, so that the analysis
 * (`rebound pipe-stats`) can give every statistic its standard error from independent
 * particles (one-way coupling: particles do not interact). Each rank adds what its particles
 * do; the last step sums the ranks into particles.csv (rank 0).
 *
 * Row of one particle (nb = n_bins, bins of width D/nb across the pipe, from -R to R):
 *   n            samples (end of each time step in the window)
 *   dist         axial distance travelled in the window, sum of u_x dt (m)
 *   hits         wall rebounds in the window (status RW_OK)
 *   sum_y        sum of the heights y at the samples (m)
 *   cy[nb]       samples in each horizontal slab (bins of y: the vertical diameter)
 *   cz[nb]       samples in each vertical slab (bins of z: the horizontal diameter)
 *   ux[nb], ux2[nb], ur[nb], ur2[nb]
 *                per y slab: sums of the axial velocity u_x and the wall-normal (radial,
 *                positive towards the wall) velocity u_r, and of their squares
 *   sy[nb]       samples along the vertical diameter: bins of y within the strip |z| < R/5
 *   sz[nb]       samples along the horizontal diameter: bins of z within |y| < R/5        */

#include "cs_defs.h"
#include "cs_headers.h"

/* Is the current time step in the sampling window? */
int pipe_in_window(void);

/* Adds the end-of-step state of every local particle (call once per step in the window). */
void pipe_tally_sample(const cs_lagr_particle_set_t *p_set);

/* Counts one wall hit of particle `pid` in the window. */
void pipe_tally_hit(unsigned long long pid);

/* Sums the ranks and writes particles.csv on rank 0 (call at the last step, on every rank). */
void pipe_tally_write(void);

#endif
