!> Host-code check (plain Makefile, pkg-config): the DW equilibrium at alpha = 0.3, mu = 1,
!> a* = 0.2 against the mpmath reference row of test/data/dw.txt. The host has names of its
!> own that libraries commonly export (wp, dp, pi, status, model, error, n, x) and uses
!> wavyadhesion without `only:`: the library's names do not collide with them.
program consumer_make
   use wavyadhesion
   implicit none
   integer, parameter :: dp = kind(1.0d0), wp = dp
   real(wp), parameter :: pi = 3.14159265358979323846_wp
   real(wp), parameter :: c_ref = 0.32795133117893904447_wp, p_ref = 0.17439576801132992591_wp
   type(params_type) :: params
   type(state_type) :: state
   integer :: status, model, n
   logical :: error
   real(wa_wp) :: x
   model = model_dw
   n = 1
   x = 0.2_wa_wp
   call new_params(alpha=0.3_wp, mu=1.0_wp, params=params, status=status)
   if (status /= wa_ok) error stop "new_params failed"
   call dw_equilibrium(params, x, state, status)
   if (status /= wa_ok) error stop "dw_equilibrium failed"
   print '(a,a,a,f19.16,a,f19.16)', "wavyadhesion ", wa_version, ": c* = ", state%c_star, &
      "  P* = ", state%p_star
   error = abs(state%c_star - c_ref) > 1e-12_wp*c_ref .or. abs(state%p_star - p_ref) > 1e-12_wp*p_ref
   if (error .or. model /= model_dw .or. n /= 1 .or. pi < 3) &
      error stop "c* or P* differs from the reference"
end program consumer_make
