#ifndef CSWM_WALL_H
#define CSWM_WALL_H
/* The roughwall handle of a code_saturne case (every case whose wall hook calls roughwall:
 * case_src/ and pipe/case_src/): built once, at the first hit, from the case's parameters;
 * a parameter the library refuses stops the run with the library's one-line message; the
 * listing records the wall and the library's version.                                   */

#include "roughwall.h"

static inline rw_wall *
cswm_wall_new(const rw_wall_params  *p,
              const char            *what)
{
  rw_wall *wall = NULL;
  char msg[512];
  int s = rw_wall_new(p, &wall, msg, sizeof msg);
  if (s != RW_OK)
    bft_error(__FILE__, __LINE__, 0, "roughwall: %s (%s)", rw_status_string(s), msg);
  bft_printf("roughwall %s: %s (%g, %g) deg, model %d, law %d, preset %d %s\n",
             rw_version(), what, p->delta_xi_deg, p->delta_zeta_deg, p->model, p->law,
             p->preset, msg);
  return wall;
}

#endif /* CSWM_WALL_H */
