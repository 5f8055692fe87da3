!> Host-code check (CMake, find_package): the DW equilibrium at alpha = 0.3, mu = 1,
!> a* = 0.2 against the mpmath reference row of test/data/dw.txt.
program consumer_cmake
   use wavyadhesion
   implicit none
   real(wa_wp), parameter :: c_ref = 0.32795133117893904447_wa_wp, &
      p_ref = 0.17439576801132992591_wa_wp
   type(params_type) :: params
   type(state_type) :: state
   integer :: status
   call new_params(alpha=0.3_wa_wp, mu=1.0_wa_wp, params=params, status=status)
   if (status /= wa_ok) error stop "new_params failed"
   call dw_equilibrium(params, 0.2_wa_wp, state, status)
   if (status /= wa_ok) error stop "dw_equilibrium failed"
   print '(a,a,a,f19.16,a,f19.16)', "wavyadhesion ", wa_version, ": c* = ", state%c_star, &
      "  P* = ", state%p_star
   if (abs(state%c_star - c_ref) > 1e-12_wa_wp*c_ref .or. &
      abs(state%p_star - p_ref) > 1e-12_wa_wp*p_ref) &
      error stop "c* or P* differs from the reference"
end program consumer_cmake
