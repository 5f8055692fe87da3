!> W* of the smooth-adhesion (Lennard-Jones) gap-controlled cycle and the states it is
!> made of, for the independent check study/bem/check_wstar.py (not run in CI; asserts
!> nothing).
!>   cd study && fpm run --profile release wavyadhesion-lj-wstar -- ALPHA MU N SCALE [OUT]
!> Traces the curve at N points per period (0: automatic) with the step limits of
!> lj_trace_options (largest turn, changes of P* and gbar* per step) times SCALE, runs both
!> paths and prints: N, the traced points, the processor time, P_fc*, P_pf* and W* (13
!> digits). With OUT, writes for every jump of the gap path the states where it starts and
!> ends: a line "jump gbar* P*_start P*_end", then the gap over Delta of both states on the
!> N nodes x* = j/N (two columns), after a header line "law dgamma eps N".
program lj_wstar
   use, intrinsic :: iso_fortran_env, only: error_unit
   use wavyadhesion, only: params_type, new_params, lj_problem_type, lj_problem, &
      lj_branch_type, lj_trace, lj_trace_options, lj_paths, lj_cycle_type, lj_profile, &
      lj_path_jump_start, wa_ok
   use wa_kinds, only: wp
   implicit none
   integer :: n_period, status, u, k, i0, i1, j, np
   real(wp) :: alpha, mu, scale, c0, c1
   character(len=512) :: arg, out
   character(len=256) :: msg
   type(params_type) :: params
   type(lj_problem_type) :: problem
   type(lj_branch_type) :: branch
   type(lj_cycle_type) :: cycle
   type(lj_trace_options) :: opts
   real(wp), allocatable :: x(:), g0(:), g1(:), tr(:)

   if (command_argument_count() < 4) then
      write (error_unit, '(a)') "usage: wavyadhesion-lj-wstar ALPHA MU N SCALE [OUT]"
      stop 2
   end if
   call get_command_argument(1, arg); read (arg, *) alpha
   call get_command_argument(2, arg); read (arg, *) mu
   call get_command_argument(3, arg); read (arg, *) n_period
   call get_command_argument(4, arg); read (arg, *) scale
   out = ""
   if (command_argument_count() >= 5) call get_command_argument(5, out)
   msg = ""
   call new_params(alpha, mu, params, status, msg)
   call check("new_params")
   call cpu_time(c0)
   call lj_problem(params, problem, status, msg, n_period)
   call check("lj_problem")
   opts%max_turn = scale*opts%max_turn
   opts%dp_max = scale*opts%dp_max
   opts%dg_max = scale*opts%dg_max
   call lj_trace(problem, branch, status, msg, opts)
   call check("lj_trace")
   call lj_paths(problem, branch, cycle, status, msg)
   call check("lj_paths")
   call cpu_time(c1)
   np = problem%grid%n_period
   write (*, '(a,i0,a,i0,a,f0.3,a,es21.13,a,es21.13,a,es21.13)') "N ", np, " points ", &
      branch%n, " cpu_s ", c1 - c0, " P_fc ", cycle%p_fc, " P_pf ", cycle%p_pf, &
      " W_star ", cycle%w_star
   if (len_trim(out) == 0) stop
   allocate (x(np), g0(np), g1(np), tr(np))
   open (newunit=u, file=trim(out), status="replace", action="write")
   write (u, '(a,2es25.16,i8)') "law ", problem%law%dgamma, problem%law%eps, np
   do k = 1, cycle%gap%n
      if (cycle%gap%event(k) /= lj_path_jump_start) cycle
      i0 = find(cycle%gap%gbar(k), cycle%gap%p_star(k))
      i1 = find(cycle%gap%gbar(k + 1), cycle%gap%p_star(k + 1))
      call lj_profile(problem, branch%z(:, i0), x, g0, tr)
      call lj_profile(problem, branch%z(:, i1), x, g1, tr)
      write (u, '(a,3es25.16)') "jump ", cycle%gap%gbar(k), cycle%gap%p_star(k), &
         cycle%gap%p_star(k + 1)
      do j = 1, np
         write (u, '(2es25.16)') g0(j), g1(j)
      end do
   end do
   close (u)

contains

   !> The branch point with this mean gap and load.
   integer function find(g, p)
      real(wp), intent(in) :: g, p
      do find = 1, branch%n
         if (branch%gbar(find) == g .and. branch%p_star(find) == p) return
      end do
      write (error_unit, '(a)') "state of a jump not found on the branch"
      stop 1
   end function find

   subroutine check(what)
      character(len=*), intent(in) :: what
      if (status /= wa_ok) then
         write (error_unit, '(a)') what//": "//trim(msg)
         stop 1
      end if
   end subroutine check

end program lj_wstar
