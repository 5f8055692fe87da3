!> States of the smooth-adhesion (Lennard-Jones) model for the cross-check against
!> ContactMechanics + Adhesion (study/bem/crosscheck_contactmechanics.py, which runs this
!> program; not run in CI). Asserts nothing.
!>   cd study && fpm run --profile release wavyadhesion-lj-states -- ALPHA MU N M OUT
!> Traces the curve at N points per period, runs both paths on it (the cycle), and writes
!> to OUT: the wall and processor times of the trace and of the cycle, the number of
!> states, then M gap-stable states picked evenly along the trace among those that
!> interact (smallest gap below 20 eps), each with its gap field on the N nodes
!> x* = j/N, the field of its neighbour on the trace (the warm start a sweep would use)
!> and the cost of solving it alone at its fixed mean gap: from a cold start (the rigid
!> gap f - fbar + gbar*, P* the mean of the law on it) and from that neighbour, each with
!> its own problem set-up, factorisation and FFT plans.
program lj_states
   use, intrinsic :: iso_fortran_env, only: error_unit, int64
   use wavyadhesion, only: params_type, new_params, lj_problem_type, lj_problem, &
      lj_branch_type, lj_trace, lj_paths, lj_cycle_type, wa_ok
   use wa_kinds, only: wp
   use wa_bem_law, only: law_eval, law_zero
   use wa_bem_elastic, only: full_period
   use wa_bem_solver, only: jacobian_type, factor_at, newton, gap_constraint, jacobian_free
   implicit none
   integer :: n_period, m, status, u, i, k, nb, n_pick, kk
   real(wp) :: alpha, mu, eps, t_trace(2), t_cycle(2), t0(2), t1(2)
   character(len=512) :: arg, out
   character(len=256) :: msg
   type(params_type) :: params
   type(lj_problem_type) :: problem
   type(lj_branch_type) :: branch, walked
   type(lj_cycle_type) :: cycle
   integer, allocatable :: pool(:), pick(:)
   real(wp) :: cold(4), warm(4)

   if (command_argument_count() /= 5) then
      write (error_unit, '(a)') "usage: wavyadhesion-lj-states ALPHA MU N M OUT"
      stop 2
   end if
   call get_command_argument(1, arg); read (arg, *) alpha
   call get_command_argument(2, arg); read (arg, *) mu
   call get_command_argument(3, arg); read (arg, *) n_period
   call get_command_argument(4, arg); read (arg, *) m
   call get_command_argument(5, out)
   msg = ""
   call new_params(alpha, mu, params, status, msg)
   call check("new_params")

   ! the trace alone, then the cycle (a trace and both paths) as lj_cycle does it
   call clock(t0)
   call lj_problem(params, problem, status, msg, n_period)
   call check("lj_problem")
   call lj_trace(problem, branch, status, msg)
   call check("lj_trace")
   call clock(t1)
   t_trace = t1 - t0
   call clock(t0)
   call lj_problem(params, problem, status, msg, n_period)
   call lj_trace(problem, walked, status, msg)
   call check("lj_trace")
   call lj_paths(problem, walked, cycle, status, msg)
   call check("lj_paths")
   call clock(t1)
   t_cycle = t1 - t0
   eps = law_zero(problem%law)

   ! gap-stable states that interact, with a gap-stable neighbour on the trace
   pool = pack([(i, i = 2, branch%n - 1)], [(branch%stable_gap(i) .and. &
      branch%h_min(i) < 20.0_wp*eps .and. (branch%stable_gap(i - 1) .or. &
      branch%stable_gap(i + 1)), i = 2, branch%n - 1)])
   n_pick = min(m, size(pool))
   allocate (pick(n_pick))
   do k = 1, n_pick
      pick(k) = pool(1 + ((k - 1)*(size(pool) - 1))/max(n_pick - 1, 1))
   end do

   open (newunit=u, file=trim(out), status="replace", action="write")
   write (u, '(a)') "# wavyadhesion-lj-states: alpha mu N points points_cycle "// &
      "trace_wall trace_cpu cycle_wall cycle_cpu eps"
   write (u, '(2es24.16,3(1x,i0),4es14.5,es24.16)') alpha, mu, n_period, branch%n, &
      walked%n, t_trace, t_cycle, eps
   write (u, '(a)') "# per state: index P gbar a_star h_min stable_load neighbour "// &
      "cold(status iterations cpu maxdiff/eps) warm(same); then the gap field and the "// &
      "neighbour's (N values each)"
   write (u, '(i0)') n_pick
   do kk = 1, n_pick
      k = pick(kk)
      nb = k - 1
      if (.not. branch%stable_gap(nb)) nb = k + 1
      call alone(k, 0, cold)
      call alone(k, nb, warm)
      write (u, '(i0,4es24.16,1x,l1,1x,i0,2(1x,f3.0,1x,f4.0,2es12.4))') k, &
         branch%p_star(k), branch%gbar(k), branch%a_star(k), branch%h_min(k), &
         branch%stable_load(k), nb, cold, warm
      write (u, '(*(es24.16))') full_period(problem%grid, branch%z(1:branch%n_unknowns, k))
      write (u, '(*(es24.16))') full_period(problem%grid, branch%z(1:branch%n_unknowns, nb))
   end do
   close (u)

contains

   !> Solve state k alone at its mean gap: from the rigid gap (start = 0) or from the
   !> traced state start; res = (status, Newton iterations, processor seconds,
   !> max |h - h_k|/eps).
   subroutine alone(k, start, res)
      integer, intent(in) :: k, start
      real(wp), intent(out) :: res(4)
      type(lj_problem_type) :: fresh
      type(jacobian_type) :: jac
      real(wp), allocatable :: z(:), sig(:), slope(:)
      real(wp) :: s0(2), s1(2)
      integer :: n, st, n_factor, its
      call clock(s0)
      call lj_problem(params, fresh, st, msg, n_period)
      n = fresh%grid%n
      allocate (z(n + 1), sig(n), slope(n))
      if (start == 0) then
         z(1:n) = fresh%grid%f - fresh%grid%fbar + branch%gbar(k)
         call law_eval(fresh%law, z(1:n), sig, slope)
         z(n + 1) = -sum(fresh%grid%w*sig)/n_period
      else
         z = branch%z(:, start)
      end if
      n_factor = 0
      its = 0
      call factor_at(fresh, z, jac)
      call newton(fresh, gap_constraint(fresh), branch%gbar(k), z, jac, st, n_factor, its)
      call jacobian_free(jac)
      call clock(s1)
      res = [real(st, wp), real(its, wp), s1(2) - s0(2), &
         maxval(abs(z(1:n) - branch%z(1:n, k)))/eps]
   end subroutine alone

   !> Wall and processor seconds.
   subroutine clock(t)
      real(wp), intent(out) :: t(2)
      integer(int64) :: c, rate
      real :: cpu
      call system_clock(c, rate)
      call cpu_time(cpu)
      t = [real(c, wp)/real(rate, wp), real(cpu, wp)]
   end subroutine clock

   subroutine check(what)
      character(len=*), intent(in) :: what
      if (status /= wa_ok) then
         write (error_unit, '(a)') "wavyadhesion-lj-states: "//what//" failed: "//trim(msg)
         stop 1
      end if
   end subroutine check

end program lj_states
