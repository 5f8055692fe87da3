!> Benchmark of the smooth-adhesion (Lennard-Jones) cycle. Prints figures; asserts nothing.
!>   cd study && fpm run --profile release wavyadhesion-lj-benchmark [-- --max-n N] [--cap T]
!>      [--case ALPHA MU]
!> N = 256 .. max-n (default 8192, at most 16384); a size whose predicted cost (from the
!> last one and the growth so far) exceeds the cap T seconds (default 60) is skipped with
!> the reason. --case times one cycle at (ALPHA, MU) on the automatic grid instead.
!> One cycle = trace from far apart to full contact, both paths, P_fc*, P_pf*, W*.
program bench_lj
   use, intrinsic :: iso_fortran_env, only: error_unit
   use wavyadhesion
   use wa_kinds, only: wp
   implicit none
   integer :: max_n, i_arg, status, k, n, m
   character(len=64) :: arg
   character(len=256) :: msg
   type(params_type) :: params
   type(lj_cycle_type) :: cyc
   real(wp) :: t, ln(8), lt(8), slope, values(4, 8), cap, predicted, alpha, mu
   integer :: sizes(8), points, factors

   max_n = 8192
   cap = 60.0_wp
   alpha = -1.0_wp
   mu = -1.0_wp
   i_arg = 1
   do while (i_arg <= command_argument_count())
      call get_command_argument(i_arg, arg)
      select case (arg)
      case ("--help", "-h")
         write (*, '(a)') "usage: wavyadhesion-lj-benchmark [--max-n N] [--cap SECONDS] "// &
            "[--case ALPHA MU]", &
            "Times the smooth-adhesion cycle at alpha 0.3, mu 3 (automatic grid, with its", &
            "error estimate), the cost of one cycle for N = 256 .. max-n (default 8192,", &
            "at most 16384; a size predicted above the cap, default 60 s, is skipped) with", &
            "the fitted growth exponent, and the convergence table. --case: one cycle at", &
            "(ALPHA, MU) on the automatic grid only."
         stop
      case ("--case")
         call get_command_argument(i_arg + 1, arg)
         read (arg, *) alpha
         call get_command_argument(i_arg + 2, arg)
         read (arg, *) mu
         i_arg = i_arg + 2
      case ("--max-n")
         i_arg = i_arg + 1
         call get_command_argument(i_arg, arg)
         read (arg, *) max_n
      case ("--cap")
         i_arg = i_arg + 1
         call get_command_argument(i_arg, arg)
         read (arg, *) cap
      case default
         write (error_unit, '(a)') "wavyadhesion-lj-benchmark: unknown argument '"// &
            trim(arg)//"' (try --help)"
         stop 2
      end select
      i_arg = i_arg + 1
   end do

   msg = ""
   if (alpha >= 0.0_wp) then
      call new_params(alpha, mu, params, status, msg)
      call report_status("parameters")
      t = seconds()
      call one_cycle(lj_auto_n(params), points, factors)
      t = seconds() - t
      call report_status("automatic grid")
      write (*, '(a,2g12.5,a,i0,a,f9.3,a,i0,a,i0,a)') "cycle at alpha, mu =", alpha, mu, &
         " on the automatic N = ", cyc%n_period, ": ", t, " s (CPU; ", points, &
         " points, ", factors, " factorisations)"
      stop
   end if
   call new_params(0.3_wp, 3.0_wp, params, status)
   write (*, '(a)') "wavyadhesion "//wa_version//" smooth-adhesion benchmark (one core)"
   write (*, '(a)') "target (issue): full cycle at alpha 0.3, mu 3, automatic N <= 0.5 s; N = 4096 <= 5 s"
   t = seconds()
   call lj_cycle(params, cyc, status, msg, estimate=.false.)
   t = seconds() - t
   call report_status("automatic grid")
   write (*, '(a,i0,a,f8.3,a)') "cycle at the automatic N = ", cyc%n_period, ": ", t, " s (CPU)"
   t = seconds()
   call lj_cycle(params, cyc, status, msg)
   t = seconds() - t
   write (*, '(a,f8.3,a)') "same with its error estimate (the cycle at N/2 too): ", t, " s (CPU)"
   write (*, '(a,es12.4,a,es9.2)') "  P_pf* = ", cyc%p_pf, "  +- ", cyc%p_pf_err
   write (*, '(a,es12.4,a,es9.2)') "  P_fc* = ", cyc%p_fc, "  +- ", cyc%p_fc_err
   write (*, '(a,es12.4,a,es9.2)') "  snap  = ", cyc%p_snap, "  +- ", cyc%p_snap_err
   write (*, '(a,es12.4,a,es9.2)') "  W*    = ", cyc%w_star, "  +- ", cyc%w_star_err

   write (*, '(/,a)') "    N   CPU [s]  points factors             P_pf*                P_fc*"// &
      "                snap                 W*"
   m = 0
   n = 256
   do while (n <= min(max_n, 16384))
      if (m >= 1) then
         slope = 1.5_wp                   ! the growth so far, at least N^1.5
         if (m >= 2) slope = max(slope, slope_of(m))
         predicted = exp(lt(m))*2.0_wp**slope
         if (predicted > cap) then
            write (*, '(i6,a,f8.1,a,f6.1,a)') n, "  skipped: predicted ", predicted, &
               " s is above the cap of ", cap, " s (--cap)"
            n = 2*n
            cycle
         end if
      end if
      t = seconds()
      call one_cycle(n, points, factors)
      t = seconds() - t
      call report_status("fixed grid")
      m = m + 1
      sizes(m) = n
      ln(m) = log(real(n, wp))
      lt(m) = log(t)
      values(:, m) = [cyc%p_pf, cyc%p_fc, cyc%p_snap, cyc%w_star]
      write (*, '(i6,f10.3,i8,i8,4es21.12)') n, t, points, factors, values(:, m)
      n = 2*n
   end do
   if (m >= 2) then
      slope = slope_of(m)
      write (*, '(a,f6.2)') "fitted growth exponent of the cycle cost in N: ", slope
      write (*, '(/,a)') "relative change from N/2 to N:   P_pf*      P_fc*      snap       W*"
      do k = 2, m
         write (*, '(i6,a,4es11.2)') sizes(k), "                     ", &
            abs(values(:, k) - values(:, k - 1))/abs(values(:, k))
      end do
   end if

contains

   !> One cycle at n points per period (what lj_cycle does without its estimate), with
   !> the traced points and the factorisations of its trace.
   subroutine one_cycle(n, points, factors)
      integer, intent(in) :: n
      integer, intent(out) :: points, factors
      type(lj_problem_type) :: problem
      type(lj_branch_type) :: branch
      points = 0
      factors = 0
      cyc = lj_cycle_type()
      call lj_problem(params, problem, status, msg, n)
      if (status /= wa_ok) return
      call lj_trace(problem, branch, status, msg)
      if (status /= wa_ok) return
      points = branch%n
      factors = branch%n_factor
      call lj_paths(problem, branch, cyc, status, msg)
   end subroutine one_cycle

   !> Least-squares slope of log(cost) against log(N) over the first k sizes.
   real(wp) function slope_of(k)
      integer, intent(in) :: k
      slope_of = (k*sum(ln(1:k)*lt(1:k)) - sum(ln(1:k))*sum(lt(1:k)))/ &
         (k*sum(ln(1:k)**2) - sum(ln(1:k))**2)
   end function slope_of

   !> Processor time of this (single-threaded) process: the one-core cost, unaffected
   !> by other processes sharing the machine.
   real(wp) function seconds()
      call cpu_time(seconds)
   end function seconds

   subroutine report_status(what)
      character(len=*), intent(in) :: what
      if (status /= wa_ok) then
         write (error_unit, '(a)') "wavyadhesion-lj-benchmark: "//what//": "//trim(msg)
         stop 1
      end if
   end subroutine report_status

end program bench_lj
