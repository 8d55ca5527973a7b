/* Boundary zones for the box mesh written by make_mesh.py.
 *
 * GOTCHA: the code_saturne 6.0.2 preprocessor only applies Gmsh
 * $PhysicalNames for Gmsh 4.x files (they are attached in $Entities).
 * For Gmsh 2.2 files the mesh groups are the physical tag NUMBERS as
 * strings: "1" = inlet, "2" = outlet, "3" = wall (see make_mesh.py).
 * setup_case.sh defines CSWM_NAMED_GROUPS=1 when it writes a Gmsh 4.1 mesh
 * (groups then exist under both the number and the name).
 * (Using "1 or inlet" works for both but logs a warning per missing group.) */

#include "cs_defs.h"
#include <stdio.h>
#include "cs_headers.h"
#include "cswm_common.h"

BEGIN_C_DECLS

void
cs_user_zones(void)
{
#if CSWM_NAMED_GROUPS
  cs_boundary_zone_define("inlet",  "inlet",  0);
  cs_boundary_zone_define("outlet", "outlet", 0);
  cs_boundary_zone_define("wall",   "wall",   0);
#else
  cs_boundary_zone_define("inlet",  "1", 0);
  cs_boundary_zone_define("outlet", "2", 0);
  cs_boundary_zone_define("wall",   "3", 0);
#endif
}

END_C_DECLS
