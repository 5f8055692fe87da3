!> Pure-Fortran baseline for python/benchmarks/bench_overhead.py: the principal DW
!> equilibrium at alpha = 0.3, mu = 1 on n points a*_i = i/(2(n+1)), i = 1..n, stored
!> into three arrays, as the Python facade does. Prints the best of `repeats` timings.
!>   cd study && fpm run --profile release bench_overhead -- [n [repeats]]
program bench_overhead
   use, intrinsic :: iso_fortran_env, only: int64, output_unit
   use wa_kinds, only: wp
   use wavyadhesion, only: params_type, state_type, new_params, dw_equilibrium, wa_ok
   implicit none
   type(params_type) :: params
   type(state_type) :: state
   real(wp), allocatable :: a(:), c(:), p(:)
   integer, allocatable :: z(:)
   integer(int64) :: t0, t1, rate
   real(wp) :: best, elapsed
   integer :: n, repeats, i, r, status, nfail
   character(len=32) :: arg

   n = 100000
   repeats = 5
   if (command_argument_count() >= 1) then
      call get_command_argument(1, arg)
      read (arg, *) n
   end if
   if (command_argument_count() >= 2) then
      call get_command_argument(2, arg)
      read (arg, *) repeats
   end if
   allocate (a(n), c(n), p(n), z(n))
   a = [(0.5_wp*real(i, wp)/real(n + 1, wp), i=1, n)]
   call new_params(0.3_wp, 1.0_wp, params, status)
   best = huge(1.0_wp)
   nfail = 0
   do r = 1, repeats
      call system_clock(t0, rate)
      do i = 1, n
         call dw_equilibrium(params, a(i), state, status)
         if (status /= wa_ok) nfail = nfail + 1
         c(i) = state%c_star
         p(i) = state%p_star
         z(i) = state%zone_case
      end do
      call system_clock(t1)
      elapsed = real(t1 - t0, wp)/real(rate, wp)
      best = min(best, elapsed)
   end do
   write (output_unit, '(a,i0,a,i0)') "points ", n, " failures ", nfail
   write (output_unit, '(a,es12.5)') "checksum ", sum(p) + sum(c) + real(sum(z), wp)
   write (output_unit, '(a,es12.5)') "fortran_seconds ", best
end program bench_overhead
