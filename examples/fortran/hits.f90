! A small Fortran program on roughwall: the glass-steel wall of Radenkovic & Simonin (2021),
! Sec. 4, hit by 20 particles in the paper's frame (normal +y, lay +x). Prints per hit the key,
! the status, the rebound velocity and spin (17 significant digits, so the Rust test can
! check them against the Rust call bit for bit) and the candidate walls; then a bad input.
! Then what a CFD code does between two hits (rw_fluid_point): a 100 um glass bead in air near
! the wall, 3 states, each its Saffman-Mei and Magnus lifts (m/s2) and its spin after 1 ms;
! then a negative time step.
program hits
  use, intrinsic :: iso_c_binding
  use roughwall
  implicit none
  type(rw_wall_params) :: params
  type(rw_hit) :: hit
  type(rw_result) :: res
  type(rw_fluid_point) :: point
  real(c_double) :: lift_sm(3), lift_mag(3), spin(3)
  type(c_ptr) :: wall
  character(kind=c_char) :: message(256)
  integer(c_int32_t) :: status
  integer :: pid
  real(c_double) :: uh

  status = rw_wall_params_default(params)
  params%delta_xi_deg = 3.8d0
  params%delta_zeta_deg = 7.5d0
  params%law = RW_LAW_SOMMERFELD_HUBER
  params%preset = RW_PRESET_GLASS_STEEL
  params%seed = 2021_c_int64_t
  status = rw_wall_new(params, wall, message, int(size(message), c_size_t))
  if (status /= RW_OK) then
     print '(a, i0)', 'rw_wall_new failed: ', status
     stop 1
  end if
  print '(2a)', 'roughwall ', rw_version_string()
  do pid = 0, 19
     uh = 4.0d0 + 0.25d0 * pid
     hit%velocity = [uh * 0.5d0, -0.35d0 * uh, -uh * 0.866d0]
     hit%spin = [0.0d0, 0.0d0, 100.0d0 * pid]
     hit%normal = [0.0d0, 1.0d0, 0.0d0]
     hit%lay = [1.0d0, 0.0d0, 0.0d0]
     hit%wall_velocity = 0.0d0
     hit%diameter = 500.0d-6
     hit%particle_id = int(pid, c_int64_t)
     hit%collision_index = int(mod(pid, 3), c_int64_t)
     status = rw_rebound(wall, hit, res)
     print '(i3, 1x, i1, 1x, i1, 6(1x, es25.17e3), 1x, i0)', pid, mod(pid, 3), status, &
          res%velocity, res%spin, res%candidate_walls
  end do
  hit%normal = 0.0d0
  status = rw_rebound(wall, hit, res)
  print '(a, i0)', 'zero normal: status ', status
  call rw_wall_free(wall)

  ! Between hits: air at 20 C, glass, the slip and the shear of a wall cell, the spin a hit left.
  point%rho_f = 1.204d0
  point%mu_f = 1.825d-5
  point%rho_p = 2500.0d0
  point%d_p = 100.0d-6
  do pid = 0, 2
     point%slip = [1.5d0 - 0.5d0 * pid, -0.05d0 * pid, 0.02d0]
     point%vorticity = [0.0d0, 30.0d0 * pid, -800.0d0 - 400.0d0 * pid]
     point%spin = [10.0d0 * pid, -20.0d0, 3000.0d0 - 1500.0d0 * pid]
     status = rw_saffman_mei_lift(point, lift_sm)
     if (status /= RW_OK) stop 2
     status = rw_magnus_lift(point, lift_mag)
     if (status /= RW_OK) stop 2
     spin = point%spin
     status = rw_spin_relax(point, 1.0d-3, spin)
     if (status /= RW_OK) stop 2
     print '(a, i1, 9(1x, es25.17e3))', 'carrier ', pid, lift_sm, lift_mag, spin
  end do
  spin = point%spin
  status = rw_spin_relax(point, -1.0d-3, spin)
  print '(a, i0)', 'negative dt: status ', status
end program hits
