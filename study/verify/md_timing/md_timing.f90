!> Time per md_equilibrium and md_roots call (performance target, doc/accuracy-performance.md: MD <= 20 us median):
!> alpha in {0.01, 0.1, 0.3, 1, 10} x mu in {1e-3, 0.1, 1, 3, 30, 1e3} x 40 a* from 1e-6
!> to 1/2 - 1e-9; each point repeated 20 times, best of 3 (the machine is shared).
!> Run by study/md_study.sh.
program md_timing
   use, intrinsic :: iso_fortran_env, only: int64
   use wa_kinds, only: wp
   use wa_params, only: params_type, new_params
   use wa_state, only: state_type
   use wa_md, only: md_equilibrium, md_roots
   implicit none
   real(wp), parameter :: alphas(5) = [0.01_wp, 0.1_wp, 0.3_wp, 1.0_wp, 10.0_wp]
   real(wp), parameter :: mus(6) = [0.001_wp, 0.1_wp, 1.0_wp, 3.0_wp, 30.0_wp, 1000.0_wp]
   integer, parameter :: n_a = 40, reps = 20
   real(wp) :: t_eq(size(alphas)*size(mus)*n_a), t_all(size(t_eq)), a
   type(params_type) :: p
   type(state_type) :: st, sts(8)
   integer :: ia, im, k, i, j, r, status, n
   integer(int64) :: c0, c1, rate
   real(wp) :: sink
   sink = 0
   call system_clock(count_rate=rate)
   i = 0
   do ia = 1, size(alphas)
      do im = 1, size(mus)
         call new_params(alphas(ia), mus(im), p, status)
         do k = 1, n_a
            a = 1e-6_wp + (0.5_wp - 1e-6_wp - 1e-9_wp)*real(k - 1, wp)/real(n_a - 1, wp)
            i = i + 1
            t_eq(i) = huge(1.0_wp)
            t_all(i) = huge(1.0_wp)
            do j = 1, 3                       ! best of 3: the machine is shared
               call system_clock(c0)
               do r = 1, reps
                  call md_equilibrium(p, a, st, status)
                  sink = sink + st%p_star
               end do
               call system_clock(c1)
               t_eq(i) = min(t_eq(i), real(c1 - c0, wp)/real(rate, wp)/reps*1e6_wp)
               call system_clock(c0)
               do r = 1, reps
                  call md_roots(p, a, sts, n, status)
                  sink = sink + sts(1)%p_star
               end do
               call system_clock(c1)
               t_all(i) = min(t_all(i), real(c1 - c0, wp)/real(rate, wp)/reps*1e6_wp)
            end do
         end do
      end do
   end do
   call report("md_equilibrium", t_eq)
   call report("md_roots      ", t_all)
   if (sink == 12345.0_wp) print *, sink
contains
   subroutine report(name, t)
      character(len=*), intent(in) :: name
      real(wp), intent(inout) :: t(:)
      call sort(t)
      print '(a, ": median ", f8.2, " us, p90 ", f8.2, " us, max ", f8.2, " us over ", i0, " points")', &
         name, t((size(t) + 1)/2), t(int(0.9*size(t))), t(size(t)), size(t)
   end subroutine report
   subroutine sort(t)
      real(wp), intent(inout) :: t(:)
      integer :: i, j
      real(wp) :: v
      do i = 2, size(t)
         v = t(i); j = i - 1
         do while (j >= 1)
            if (t(j) <= v) exit
            t(j + 1) = t(j); j = j - 1
         end do
         t(j + 1) = v
      end do
   end subroutine sort
end program md_timing
