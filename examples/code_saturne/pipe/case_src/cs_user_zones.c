/* One boundary zone: the pipe wall (Gmsh 4.1 mesh: the group is named). After the periodic
 * join the section has no other boundary face.                                             */
#include "cs_defs.h"

#include "cs_headers.h"

BEGIN_C_DECLS

void
cs_user_zones(void)
{
  cs_boundary_zone_define("wall", "wall", 0);
}

END_C_DECLS
