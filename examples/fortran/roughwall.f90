! roughwall from Fortran: an iso_c_binding interface to the C library (include/roughwall.h).
! The derived types mirror the C structs field for field; the wall handle is a C pointer.
! Build with the library (docs/c-library.md): gfortran -c roughwall.f90, then
!   gfortran app.f90 roughwall.o -L target/release -lroughwall -Wl,-rpath,$PWD/target/release
module roughwall
  use, intrinsic :: iso_c_binding
  implicit none
  private

  ! Status codes (rw_result%status and function results) and choices of rw_wall_params.
  integer(c_int32_t), parameter, public :: RW_OK = 0, RW_NOT_APPROACHING = 1, &
       RW_INVALID_INPUT = 2, RW_INVALID_PARAMETER = 3, RW_NULL_POINTER = 4, &
       RW_INTERNAL_ERROR = 5
  integer(c_int32_t), parameter, public :: RW_LAW_ELASTIC = 0, RW_LAW_SOMMERFELD_HUBER = 1
  integer(c_int32_t), parameter, public :: RW_PRESET_NONE = 0, RW_PRESET_GLASS_STEEL = 1
  integer(c_int32_t), parameter, public :: RW_MODEL_RADENKOVIC_SIMONIN_2021 = 0, &
       RW_MODEL_SOMMERFELD_HUBER_1999 = 1, RW_MODEL_GAUSSIAN_ANGLE = 2, &
       RW_MODEL_GAUSSIAN_TILT = 3, RW_MODEL_NORMAL_PERTURBATION = 4, RW_MODEL_CALIBRATED = 5, &
       RW_MODEL_MEASURED_WALL = 6

  !> What a wall is built from (rw_wall_params): start from rw_wall_params_default.
  type, bind(c), public :: rw_wall_params
     real(c_double) :: delta_xi_deg, delta_zeta_deg
     integer(c_int32_t) :: law, preset
     real(c_double) :: e_h, alpha_e_deg, mu_0, mu_h, alpha_mu_deg
     real(c_double) :: psi
     integer(c_int64_t) :: seed
     integer(c_int32_t) :: model
     real(c_double) :: delta_gamma_deg
     type(c_ptr) :: escape_table_csv   ! C_NULL_PTR: the built-in table
     type(c_ptr) :: wall_table_text    ! RW_MODEL_MEASURED_WALL only: its table's text
  end type rw_wall_params

  !> One particle-wall hit in global axes, SI units (rw_hit).
  type, bind(c), public :: rw_hit
     real(c_double) :: velocity(3), spin(3), normal(3), lay(3), wall_velocity(3)
     real(c_double) :: diameter
     integer(c_int64_t) :: particle_id, collision_index
  end type rw_hit

  !> The rebound of a hit (rw_result).
  type, bind(c), public :: rw_result
     real(c_double) :: velocity(3), spin(3)
     real(c_double) :: gamma, gamma_star
     integer(c_int32_t) :: candidate_walls
     integer(c_int32_t) :: status
  end type rw_result

  !> The carrier fluid and a particle where it is (rw_fluid_point), for the spin and the lifts
  !> between hits: slip = fluid velocity seen - particle velocity, vorticity = curl of the
  !> fluid velocity, spin = the particle's angular velocity.
  type, bind(c), public :: rw_fluid_point
     real(c_double) :: rho_f, mu_f, rho_p, d_p
     real(c_double) :: slip(3), vorticity(3), spin(3)
  end type rw_fluid_point

  public :: rw_wall_params_default, rw_wall_new, rw_wall_free, rw_rebound, rw_element_impact_angle, &
       rw_spin_relax, rw_saffman_mei_lift, rw_magnus_lift, rw_version_string

  interface
     integer(c_int32_t) function rw_wall_params_default(params) bind(c, name="rw_wall_params_default")
       import :: c_int32_t, rw_wall_params
       type(rw_wall_params), intent(out) :: params
     end function rw_wall_params_default

     integer(c_int32_t) function rw_wall_new(params, wall, message, message_len) bind(c, name="rw_wall_new")
       import :: c_int32_t, c_ptr, c_char, c_size_t, rw_wall_params
       type(rw_wall_params), intent(in) :: params
       type(c_ptr), intent(out) :: wall
       character(kind=c_char), intent(out) :: message(*)
       integer(c_size_t), value :: message_len
     end function rw_wall_new

     subroutine rw_wall_free(wall) bind(c, name="rw_wall_free")
       import :: c_ptr
       type(c_ptr), value :: wall
     end subroutine rw_wall_free

     integer(c_int32_t) function rw_rebound(wall, hit, result) bind(c, name="rw_rebound")
       import :: c_int32_t, c_ptr, rw_hit, rw_result
       type(c_ptr), value :: wall
       type(rw_hit), intent(in) :: hit
       type(rw_result), intent(out) :: result
     end function rw_rebound

     ! Impact angle (rad) on the wall element that produced the rebound (for erosion laws).
     real(c_double) function rw_element_impact_angle(hit, result) bind(c, name="rw_element_impact_angle")
       import :: c_double, rw_hit, rw_result
       type(rw_hit), intent(in) :: hit
       type(rw_result), intent(in) :: result
     end function rw_element_impact_angle

     ! The particle's spin after dt in the fluid (rotational drag), into spin(3).
     integer(c_int32_t) function rw_spin_relax(point, dt, spin) bind(c, name="rw_spin_relax")
       import :: c_int32_t, c_double, rw_fluid_point
       type(rw_fluid_point), intent(in) :: point
       real(c_double), value :: dt
       real(c_double), intent(inout) :: spin(3)
     end function rw_spin_relax

     ! The Saffman-Mei and the Magnus lift as accelerations (m/s2), into acceleration(3).
     integer(c_int32_t) function rw_saffman_mei_lift(point, acceleration) &
          bind(c, name="rw_saffman_mei_lift")
       import :: c_int32_t, c_double, rw_fluid_point
       type(rw_fluid_point), intent(in) :: point
       real(c_double), intent(out) :: acceleration(3)
     end function rw_saffman_mei_lift

     integer(c_int32_t) function rw_magnus_lift(point, acceleration) bind(c, name="rw_magnus_lift")
       import :: c_int32_t, c_double, rw_fluid_point
       type(rw_fluid_point), intent(in) :: point
       real(c_double), intent(out) :: acceleration(3)
     end function rw_magnus_lift

     type(c_ptr) function rw_version() bind(c, name="rw_version")
       import :: c_ptr
     end function rw_version
  end interface

contains

  !> The library version as a Fortran string.
  function rw_version_string() result(v)
    character(len=:), allocatable :: v
    character(kind=c_char), pointer :: chars(:)
    integer :: n
    call c_f_pointer(rw_version(), chars, [32])
    n = 0
    do while (n < 32)
       if (chars(n + 1) == c_null_char) exit
       n = n + 1
    end do
    allocate(character(len=n) :: v)
    v = transfer(chars(1:n), v)
  end function rw_version_string
end module roughwall
