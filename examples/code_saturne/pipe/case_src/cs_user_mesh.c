/* The pipe section is streamwise periodic: its inlet (x = 0) and outlet (x = L) faces,
 * node-for-node translates in the mesh written by pipe.geo, are joined into a periodic pair. */
#include "cs_defs.h"

#include "cs_headers.h"
#include "pipe_params.h"

BEGIN_C_DECLS

void
cs_user_periodicity(void)
{
  const double trans[3] = {pipe_params()->length, 0., 0.};
  cs_join_perio_add_translation("inlet or outlet", 0.1, 25., 0, 0, trans);
}

END_C_DECLS
