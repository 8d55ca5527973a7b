/* Reads `pipe.params` (see pipe_params.h). */
#include "cs_defs.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cs_headers.h"
#include "pipe_params.h"

BEGIN_C_DECLS

static pipe_params_t _p;
static int _read = 0;

static void
_set(const char *key, const char *val)
{
  char *end = NULL;
  double v = strtod(val, &end);
  if (end == val)
    bft_error(__FILE__, __LINE__, 0, "pipe.params: key %s: value '%s' is not a number", key, val);
#define D(name) if (strcmp(key, #name) == 0) { _p.name = v; return; }
#define I(name) if (strcmp(key, #name) == 0) { _p.name = (int)v; return; }
  I(phase) I(nt) D(dt) D(diameter_pipe) D(length) D(u_bulk) I(wall) D(delta_xi_deg)
  D(delta_zeta_deg) I(model) I(law) I(preset) I(n_particles) D(d_p) D(rho_p)
  I(dispersion) D(t_sample) I(n_bins) I(log_hits) I(mesh_sides) I(spin) I(saffman) I(magnus)
  I(complete_langevin) I(trace) D(kick) I(nt_restart)
#undef D
#undef I
  if (strcmp(key, "seed") == 0) { _p.seed = strtoull(val, NULL, 10); return; }
  bft_error(__FILE__, __LINE__, 0, "pipe.params: unknown key '%s'", key);
}

FILE *
pipe_rank_csv(const char *stem, const char *header)
{
  char name[128];
  snprintf(name, sizeof name, "%s_rank%04d.csv", stem,
           cs_glob_rank_id < 0 ? 0 : cs_glob_rank_id);
  FILE *f = fopen(name, "w");
  if (f == NULL)
    bft_error(__FILE__, __LINE__, 0, "cannot open %s", name);
  fprintf(f, "%s\n", header);
  return f;
}

const pipe_params_t *
pipe_params(void)
{
  if (_read)
    return &_p;
  memset(&_p, 0, sizeof _p);
  _p.n_bins = 20;
  FILE *f = fopen("pipe.params", "r");
  if (f == NULL)
    bft_error(__FILE__, __LINE__, 0, "pipe.params: not found in the run directory");
  char line[256];
  while (fgets(line, sizeof line, f) != NULL) {
    char key[64], val[128];
    int n = sscanf(line, "%63s %127s", key, val);
    if (line[0] == '#' || n <= 0)
      continue;
    if (n == 1)
      bft_error(__FILE__, __LINE__, 0, "pipe.params: key %s has no value", key);
    _set(key, val);
  }
  fclose(f);
  if (_p.nt <= 0 || !(_p.dt > 0) || !(_p.diameter_pipe > 0) || !(_p.length > 0))
    bft_error(__FILE__, __LINE__, 0, "pipe.params: nt, dt, diameter_pipe and length must be > 0");
  if (_p.n_bins < 2 || _p.n_bins > 200)
    bft_error(__FILE__, __LINE__, 0, "pipe.params: n_bins %d: allowed 2 ... 200", _p.n_bins);
  /* the complete model is a dispersion model: without dispersion there is none to run */
  if (!_p.dispersion)
    _p.complete_langevin = 0;
  _read = 1;
  return &_p;
}

END_C_DECLS
