!-------------------------------------------------------------------------------
! Fluid boundary conditions (required as no setup.xml is used).
! All boundary faces are smooth walls: in the box cases the fluid, initially
! at rest, stays at rest; the periodic pipe (pipe/) has no other boundary.
! Particle boundary conditions are set separately, per boundary zone, in
! cs_user_lagr_boundary_conditions.c.
!-------------------------------------------------------------------------------
subroutine cs_f_user_boundary_conditions &
 ( nvar   , nscal  ,                                              &
   icodcl , itrifb , itypfb , izfppp ,                            &
   dt     ,                                                       &
   rcodcl )

use paramx
use numvar
use optcal
use cstphy
use cstnum
use entsor
use parall
use period
use ppppar
use ppthch
use ppincl
use mesh
use field
use iso_c_binding
use cs_c_bindings

implicit none

integer          nvar   , nscal
integer          icodcl(nfabor,nvar)
integer          itrifb(nfabor), itypfb(nfabor)
integer          izfppp(nfabor)
double precision dt(ncelet)
double precision rcodcl(nfabor,nvar,3)

integer          ifac

do ifac = 1, nfabor
  itypfb(ifac) = iparoi
enddo

return
end subroutine cs_f_user_boundary_conditions
