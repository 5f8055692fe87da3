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
   call resolve_params(opts, params)
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

   !> All states of a model at one a*; Westergaard and JKR have no cohesive zone (c* = a*).
   function states_at(model, params, a_star) result(states)
      integer, intent(in) :: model
      type(params_type), intent(in) :: params
      real(wp), intent(in) :: a_star
      type(state_type), allocatable :: states(:)
      type(state_type) :: buffer(8)
      character(len=256) :: msg
      integer :: n, status

      msg = ""
      status = wa_ok
      select case (model)
      case (model_westergaard, model_jkr)
         n = 1
         buffer(1)%a_star = a_star
         buffer(1)%c_star = a_star
         buffer(1)%zone_case = merge(zone_full_contact, zone_inside, a_star == 0.5_wp)
         if (model == model_jkr) then
            buffer(1)%p_star = jkr_load(params%alpha, a_star)
         else
            buffer(1)%p_star = westergaard_load(a_star)
         end if
      case (model_dw)
         call dw_roots(params, a_star, buffer, n, status, msg)
      case default
         call md_roots(params, a_star, buffer, n, status, msg)
      end select
      if (status /= wa_ok) call numerical_error(status, msg)
      states = buffer(1:n)
   end function states_at

   !> branch: the principal equilibrium curve sampled on a uniform a* grid. (Pseudo-
   !> arclength continuation with located folds replaces this sampling in a later version.)
   subroutine run_branch(opts, params, unit)
      type(cli_options), intent(in) :: opts
      type(params_type), intent(in) :: params
      integer, intent(in) :: unit
      integer, parameter :: n = 200
      type(state_type) :: s(n)
      real(wp) :: a(n), slope
      integer :: i, event

      if (allocated(opts%a_star)) call usage_error("branch takes no --a-star")
      a = [(0.5_wp*real(i, wp)/real(n + 1, wp), i=1, n)]
      do i = 1, n
         s(i) = principal(opts%model, params, a(i))
      end do
      call write_header(unit, opts%format, "equilibrium branch (sampled on a uniform a* grid)", &
         model_name(opts%model), params, "a_star c_star P_star b_star zone_case stable event", &
         [character(len=80) :: "b_star = a* + 0.4 (c* - a*); stable: dP*/da* > 0 (load control)", &
         "event: 0 none, 1 fold, 2 zone-case switch, 3 jump start, 4 jump end,", &
         "       5 full contact reached, 6 full contact left, 7 pull-off, 8 branch end"])
      do i = 1, n
         slope = (s(min(i + 1, n))%p_star - s(max(i - 1, 1))%p_star)
         event = merge(8, 0, i == 1 .or. i == n)
         call write_row(unit, opts%format, [s(i)%a_star, s(i)%c_star, s(i)%p_star, &
            s(i)%a_star + 0.4_wp*(s(i)%c_star - s(i)%a_star)], &
            [s(i)%zone_case, merge(1, 0, slope > 0.0_wp), event])
      end do
   end subroutine run_branch

   function principal(model, params, a_star) result(state)
      integer, intent(in) :: model
      type(params_type), intent(in) :: params
      real(wp), intent(in) :: a_star
      type(state_type) :: state
      type(state_type), allocatable :: all(:)
      character(len=256) :: msg
      integer :: status
      msg = ""
      select case (model)
      case (model_dw)
         call dw_equilibrium(params, a_star, state, status, msg)
      case (model_md)
         call md_equilibrium(params, a_star, state, status, msg)
      case default
         all = states_at(model, params, a_star)
         state = all(1)
         status = wa_ok
      end select
      if (status /= wa_ok) call numerical_error(status, msg)
   end function principal

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
         "  branch    the equilibrium curve P*(a*), c*(a*) (default; alpha=0.3, mu=1, dw)", &
         "  point     every equilibrium at given a*: --a-star X[,X...]", &
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
