!> `wavyadhesion`: the command-line driver (SPEC section 7). Prints tables of equilibria;
!> usage errors exit with status 2, numerical failures with status 1.
program wavyadhesion_cli
   use, intrinsic :: iso_fortran_env, only: output_unit, error_unit
   use, intrinsic :: ieee_arithmetic, only: ieee_is_nan
   use wavyadhesion
   use wa_cli_options, only: cli_options, parse_command_line, model_name
   use wa_cli_table, only: write_header, write_row, format_real
   implicit none

   type(cli_options) :: opts
   character(len=:), allocatable :: error
   type(params_type) :: params
   integer :: unit, ios

   call parse_command_line(opts, error)
   if (allocated(error)) call usage_error(error)
   if (opts%help) then
      call print_help()
      stop
   end if
   if (opts%version) then
      write (output_unit, '(a)') "wavyadhesion "//wa_version
      stop
   end if
   if (opts%command /= "critical") call resolve_params(opts, params)
   unit = output_unit
   if (len(opts%output) > 0) then
      open (newunit=unit, file=opts%output, status="replace", action="write", iostat=ios)
      if (ios /= 0) call usage_error("--output: cannot open '"//opts%output//"' for writing")
   end if

   select case (opts%command)
   case ("point")
      call run_point(opts, params, unit)
   case ("branch")
      call run_branch(opts, params, unit)
   case ("path")
      call run_path(opts, params, unit)
   case ("critical")
      call run_critical(opts, unit)
   case default
      call usage_error("'"//opts%command//"' is not available in this version yet")
   end select

contains

   !> alpha, mu from --alpha/--mu (defaults 0.3, 1) or from the SI options.
   subroutine resolve_params(opts, params)
      type(cli_options), intent(in) :: opts
      type(params_type), intent(out) :: params
      type(scales_type) :: scales
      character(len=256) :: msg
      real(wp) :: alpha, mu, estar
      integer :: status

      msg = ""
      if (.not. ieee_is_nan(opts%period)) then
         estar = opts%estar
         if (ieee_is_nan(estar)) then
            call reduced_modulus(opts%e1, opts%nu1, opts%e2, opts%nu2, estar, status, msg)
            if (status /= wa_ok) call usage_error("--E1/--nu1/--E2/--nu2 (or --Estar): "//trim(msg))
         end if
         call dimensional_params(estar, opts%period, opts%amplitude, opts%work, opts%peak, &
            params, scales, status, msg)
         if (status /= wa_ok) call usage_error(trim(msg))
         return
      end if
      alpha = 0.3_wp
      mu = 1.0_wp
      if (allocated(opts%alpha)) alpha = single(opts%alpha, "--alpha")
      if (allocated(opts%mu)) mu = single(opts%mu, "--mu")
      call new_params(alpha, mu, params, status, msg)
      if (status /= wa_ok) call usage_error("--"//trim(msg))
   end subroutine resolve_params

   real(wp) function single(values, name)
      real(wp), intent(in) :: values(:)
      character(len=*), intent(in) :: name
      if (size(values) /= 1) call usage_error(name//" takes one value for this subcommand")
      single = values(1)
   end function single

   !> point: every equilibrium at each a* (SPEC section 7).
   subroutine run_point(opts, params, unit)
      type(cli_options), intent(in) :: opts
      type(params_type), intent(in) :: params
      integer, intent(in) :: unit
      type(state_type), allocatable :: rows(:)
      integer :: i

      if (.not. allocated(opts%a_star)) call usage_error("point needs --a-star X[,X...]")
      do i = 1, size(opts%a_star)
         if (.not. (opts%a_star(i) >= 0.0_wp .and. opts%a_star(i) <= 0.5_wp)) &
            call usage_error("--a-star: "//format_real(opts%a_star(i))// &
            " is outside its valid range [0, 1/2]")
      end do
      allocate (rows(0))
      do i = 1, size(opts%a_star)
         rows = [rows, states_at(opts%model, params, opts%a_star(i))]
      end do
      call write_header(unit, opts%format, "equilibria at given a*", model_name(opts%model), &
         params, "a_star c_star P_star zone_case", &
         [character(len=60) :: "zone_case: 1 a*<c*<1/2, 2 c*=1/2, 3 full contact"])
      do i = 1, size(rows)
         call write_row(unit, opts%format, [rows(i)%a_star, rows(i)%c_star, rows(i)%p_star], &
            [rows(i)%zone_case])
      end do
   end subroutine run_point

   !> All states of a model at one a* (Westergaard and JKR: one, with c* = a*).
   function states_at(model, params, a_star) result(states)
      integer, intent(in) :: model
      type(params_type), intent(in) :: params
      real(wp), intent(in) :: a_star
      type(state_type), allocatable :: states(:)
      type(state_type) :: buffer(8)
      character(len=256) :: msg
      integer :: n, status

      msg = ""
      call model_roots(model, params, a_star, buffer, n, status, msg)
      if (status /= wa_ok) call numerical_error(status, msg)
      states = buffer(1:n)
   end function states_at

   !> branch: the equilibrium curve by continuation, with its events.
   subroutine run_branch(opts, params, unit)
      type(cli_options), intent(in) :: opts
      type(params_type), intent(in) :: params
      integer, intent(in) :: unit
      type(branch_type) :: b
      character(len=256) :: msg
      integer :: i, status

      if (allocated(opts%a_star)) call usage_error("branch takes no --a-star")
      msg = ""
      call trace_branch(opts%model, params, b, status, msg)
      if (status /= wa_ok) call numerical_error(status, msg)
      call write_header(unit, opts%format, "equilibrium branch (pseudo-arclength continuation)", &
         model_name(opts%model), params, "a_star c_star P_star b_star zone_case stable event", &
         [character(len=80) :: "b_star = a* + 0.4 (c* - a*); stable: 1 = stable under load control", &
         event_legend(1), event_legend(2), event_legend(3)])
      do i = 1, b%n
         call write_row(unit, opts%format, [b%a_star(i), b%c_star(i), b%p_star(i), &
            b%a_star(i) + 0.4_wp*(b%c_star(i) - b%a_star(i))], &
            [b%zone_case(i), merge(1, 0, b%stable(i)), b%event(i)])
      end do
   end subroutine run_branch

   !> path: the events of loading (stage 1) and unloading (stage 2).
   subroutine run_path(opts, params, unit)
      type(cli_options), intent(in) :: opts
      type(params_type), intent(in) :: params
      integer, intent(in) :: unit
      type(path_type) :: path
      character(len=256) :: msg
      integer :: i, status

      msg = ""
      call load_path(opts%model, params, path, status, msg)
      if (status /= wa_ok) call numerical_error(status, msg)
      call write_header(unit, opts%format, "load-controlled loading and unloading", &
         model_name(opts%model), params, "stage event a_star c_star P_star", &
         [character(len=80) :: "stage: 1 loading, 2 unloading", event_legend(1), &
         event_legend(2), "P_fc = "//format_real(path%p_fc)//"  P_pf = "// &
         format_real(path%p_pf), "P-a hysteresis loop area = "//format_real(path%loop_area)])
      do i = 1, path%n
         call write_row_ints_first(unit, opts%format, [path%stage(i), path%event(i)], &
            [path%a_star(i), path%c_star(i), path%p_star(i)])
      end do
   end subroutine run_path

   !> critical: P_fc and P_pf over alpha x mu.
   subroutine run_critical(opts, unit)
      type(cli_options), intent(in) :: opts
      integer, intent(in) :: unit
      real(wp), allocatable :: alpha(:), mu(:), p_fc(:, :), p_pf(:, :)
      integer, allocatable :: fc_mech(:, :), pf_mech(:, :)
      character(len=256) :: msg
      integer :: i, j, status
      real(wp) :: t0, t1
      logical :: progress

      alpha = [0.3_wp]
      mu = [1.0_wp]
      if (allocated(opts%alpha)) alpha = opts%alpha
      if (allocated(opts%mu)) mu = opts%mu
      allocate (p_fc(size(mu), size(alpha)), p_pf(size(mu), size(alpha)), &
         fc_mech(size(mu), size(alpha)), pf_mech(size(mu), size(alpha)))
      call cpu_time(t0)
      progress = .false.
      msg = ""
      do j = 1, size(alpha)
         call critical_sweep(opts%model, alpha(j), mu, p_fc(:, j), p_pf(:, j), fc_mech(:, j), &
            pf_mech(:, j), status, msg)
         if (status == wa_invalid_argument) call usage_error("--"//trim(msg))
         if (status /= wa_ok) call numerical_error(status, msg)
         call cpu_time(t1)
         if (t1 - t0 > 1.0_wp .and. isatty(error_unit)) progress = .true.
         if (progress) write (error_unit, '(a,i0,a,i0)') "critical: alpha ", j, " of ", size(alpha)
      end do
      call write_header(unit, opts%format, "critical forces (full contact, pull-off)", &
         model_name(opts%model), columns="alpha mu P_fc P_pf", notes=[character(len=120) :: &
         "P_fc: load at which full contact is first reached (loading from P* = 0)", &
         "P_pf: pull-off load on unloading from full contact (-Infinity: never)", &
         mechanism_notes(opts, alpha, mu, fc_mech, pf_mech)])
      do j = 1, size(alpha)
         do i = 1, size(mu)
            call write_row(unit, opts%format, [alpha(j), mu(i), p_fc(i, j), p_pf(i, j)])
         end do
      end do
   end subroutine run_critical

   !> Header lines locating in mu each change of mechanism (table format only).
   function mechanism_notes(opts, alpha, mu, fc_mech, pf_mech) result(notes)
      type(cli_options), intent(in) :: opts
      real(wp), intent(in) :: alpha(:), mu(:)
      integer, intent(in) :: fc_mech(:, :), pf_mech(:, :)
      character(len=120), allocatable :: notes(:)
      character(len=*), parameter :: names(0:3) = [character(len=12) :: "gradual", &
         "jump case 1", "jump case 2", "snap at P=0"]
      character(len=256) :: msg
      real(wp) :: mu_c
      integer :: i, j, which, status, m(2)
      allocate (notes(0))
      if (opts%format == "csv") return
      do j = 1, size(alpha)
         do i = 1, size(mu) - 1
            do which = 1, 2
               if (which == 1) m = fc_mech(i:i + 1, j)
               if (which == 2) m = pf_mech(i:i + 1, j)
               if (m(1) == m(2)) cycle
               call mechanism_change(opts%model, alpha(j), which, mu(i), mu(i + 1), mu_c, status, msg)
               if (status /= wa_ok) call numerical_error(status, msg)
               notes = [notes, "alpha "//format_real(alpha(j))//" mu "//format_real(mu_c)// &
                  merge(" P_fc: ", " P_pf: ", which == 1)//trim(names(m(1)))//" -> "// &
                  trim(names(m(2)))]
            end do
         end do
      end do
   end function mechanism_notes

   function event_legend(line) result(text)
      integer, intent(in) :: line
      character(len=80) :: text
      if (line == 1) then
         text = "event: 0 none, 1 fold, 2 zone-case switch, 3 jump start, 4 jump end,"
      else if (line == 2) then
         text = "       5 full contact reached, 6 full contact left, 7 pull-off, 8 branch end,"
      else
         text = "       9 a*-turn (a* turns back, not a fold; stability unchanged)"
      end if
   end function event_legend

   subroutine write_row_ints_first(unit, format, ints, reals)
      integer, intent(in) :: unit
      character(len=*), intent(in) :: format
      integer, intent(in) :: ints(:)
      real(wp), intent(in) :: reals(:)
      character(len=1) :: sep
      sep = merge(",", " ", format == "csv")
      write (unit, '(i0,a,i0,a)', advance="no") ints(1), sep, ints(2), sep
      call write_row(unit, format, reals)
   end subroutine write_row_ints_first

   subroutine usage_error(message)
      character(len=*), intent(in) :: message
      write (error_unit, '(a)') "wavyadhesion: "//message
      write (error_unit, '(a)') "Try 'wavyadhesion --help'."
      stop 2, quiet=.true.
   end subroutine usage_error

   subroutine numerical_error(status, message)
      integer, intent(in) :: status
      character(len=*), intent(in) :: message
      write (error_unit, '(a)') "wavyadhesion: "//status_message(status)//": "//trim(message)// &
         " (no table written)"
      stop 1, quiet=.true.
   end subroutine numerical_error

   subroutine print_help()
      write (output_unit, '(a)') &
         "Usage: wavyadhesion [SUBCOMMAND] [OPTIONS]", &
         "", &
         "Adhesive contact of a wavy elastic surface against a flat (Westergaard, JKR,", &
         "double-Westergaard, Maugis-Dugdale). Dimensionless loads P* = mean traction/p*,", &
         "p* = pi E* Delta/L; widths a* = a/L, c* = c/L.", &
         "", &
         "Subcommands:", &
         "  branch    the equilibrium curve P*(a*), c*(a*) with folds and case switches", &
         "            (default; alpha=0.3, mu=1, dw)", &
         "  point     every equilibrium at given a*: --a-star X[,X...]", &
         "  path      loading and unloading under load control: jumps, full contact, pull-off", &
         "  critical  P_fc and P_pf over --alpha A[,A...] and --mu U[,U...] or", &
         "            --mu-range LO:HI:N[:log]", &
         "", &
         "Options:", &
         "  --model M          westergaard | jkr | dw | md (default dw)", &
         "  --alpha A          Johnson's parameter, > 0 (default 0.3)", &
         "  --mu U             transition parameter, >= 0 (default 1)", &
         "  --a-star X[,X...]  contact half-widths over the period, in [0, 1/2]", &
         "  --format F         table (default, # comments + numeric rows) | csv", &
         "  --output FILE      write the table to FILE instead of standard output", &
         "  --help, --version", &
         "SI input instead of --alpha/--mu:", &
         "  --E1 --nu1 --E2 --nu2 (or --Estar) [Pa], --period --amplitude [m],", &
         "  --work-of-adhesion [J/m^2], --peak-stress [Pa]", &
         "", &
         "Exit status: 0 ok, 1 numerical failure (no table written), 2 usage error."
   end subroutine print_help

end program wavyadhesion_cli
