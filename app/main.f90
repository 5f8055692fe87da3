!> `wavyadhesion`: the command-line driver (SPEC section 7). Prints tables of equilibria;
!> usage errors exit with status 2, numerical failures with status 1. The table goes
!> through wa_cli_output: write errors are detected and `--output FILE` is replaced only
!> when the whole table was written.
program wavyadhesion_cli
   use, intrinsic :: iso_fortran_env, only: error_unit
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
   use wavyadhesion
   use wa_kinds, only: wp
   use wa_cli_options, only: cli_options, parse_command_line, model_name, given, si_given, &
      option_message
   use wa_cli_table, only: write_header, write_row, format_real
   use wa_cli_output, only: sink_type, open_sink, put_line, close_sink, discard_sink
   implicit none

   type(cli_options) :: opts
   character(len=:), allocatable :: error
   type(params_type) :: params
   !> Where the table goes; usage_error and numerical_error discard it
   type(sink_type) :: out
   logical :: ok, rows_failed, no_directory

   call parse_command_line(opts, error)
   if (allocated(error)) call usage_error(error)
   if (opts%help .or. opts%version) then
      call open_sink(out, "", ok)
      if (ok .and. opts%help) call print_help()
      if (ok .and. .not. opts%help) call put_line(out, "wavyadhesion "//wa_version)
      if (ok) call close_sink(out, ok)
      if (.not. ok) stop 1, quiet=.true.
      stop
   end if
   if ((opts%command /= "critical" .and. opts%command /= "map") .or. si_given(opts)) &
      call resolve_params(opts, params)
   call open_sink(out, opts%output, ok, no_directory)
   if (.not. ok .and. no_directory) then            ! a bad --output: a usage error
      write (error_unit, '(a)') "Try 'wavyadhesion --help'."
      stop 2, quiet=.true.
   end if
   if (.not. ok) stop 1, quiet=.true.               ! a write error (its reason is printed)

   rows_failed = .false.
   select case (opts%command)
   case ("point")
      call run_point(opts, params)
   case ("branch")
      call run_branch(opts, params)
   case ("path")
      if (allocated(opts%control)) then
         if (opts%control == "gap") call run_gap_path(opts, params)
      end if
      if (.not. allocated(opts%control)) then
         call run_path(opts, params)
      else if (opts%control == "load") then
         call run_path(opts, params)
      end if
   case ("critical")
      if (allocated(opts%control)) then
         if (opts%control == "gap") call run_gap_critical(opts, params, rows_failed)
      end if
      if (.not. allocated(opts%control)) then
         call run_critical(opts, params, rows_failed)
      else if (opts%control == "load") then
         call run_critical(opts, params, rows_failed)
      end if
   case ("map")
      call run_map(opts)
   case ("profile")
      call run_profile(opts, params)
   case ("gaplaw")
      call run_gaplaw(opts, params)
   case default
      call usage_error("'"//opts%command//"' is not available in this version yet")
   end select
   call close_sink(out, ok)
   if (.not. ok) stop 1, quiet=.true.
   if (rows_failed) stop 1, quiet=.true.

contains

   !> alpha, mu from --alpha/--mu (defaults 0.3, 1) or from the SI options (the parser
   !> has checked that the SI set is complete and not mixed with --alpha/--mu).
   subroutine resolve_params(opts, params)
      type(cli_options), intent(in) :: opts
      type(params_type), intent(out) :: params
      type(scales_type) :: scales
      character(len=256) :: msg
      real(wp) :: alpha, mu, estar
      integer :: status

      msg = ""
      if (si_given(opts)) then
         estar = opts%estar
         if (.not. given(opts, "--Estar")) then
            call reduced_modulus(opts%e1, opts%nu1, opts%e2, opts%nu2, estar, status, msg)
            if (status /= wa_ok) call usage_error("--E1/--nu1/--E2/--nu2: "//option_message(trim(msg)))
         end if
         call dimensional_params(estar, opts%period, opts%amplitude, opts%work, opts%peak, &
            params, scales, status, msg)
         if (status /= wa_ok) call usage_error(option_message(trim(msg)))
         return
      end if
      alpha = 0.3_wp
      mu = 1.0_wp
      if (allocated(opts%alpha)) alpha = single(opts%alpha, "--alpha")
      if (allocated(opts%mu)) mu = single(opts%mu, "--mu")
      call new_params(alpha, mu, params, status, msg)
      if (status /= wa_ok) call usage_error(option_message(trim(msg)))
   end subroutine resolve_params

   real(wp) function single(values, name)
      real(wp), intent(in) :: values(:)
      character(len=*), intent(in) :: name
      if (size(values) /= 1) call usage_error(name//" takes one value for this subcommand")
      single = values(1)
   end function single

   !> point: every equilibrium at each a* (SPEC section 7). Linear in the number of a*:
   !> the rows are kept in an array that doubles when full.
   subroutine run_point(opts, params)
      type(cli_options), intent(in) :: opts
      type(params_type), intent(in) :: params
      type(state_type), allocatable :: rows(:), grown(:), states(:)
      integer :: i, n_rows, n

      if (.not. allocated(opts%a_star)) call usage_error("point needs --a-star X[,X...]")
      do i = 1, size(opts%a_star)
         if (.not. (opts%a_star(i) >= 0.0_wp .and. opts%a_star(i) <= 0.5_wp)) &
            call usage_error("--a-star: "//format_real(opts%a_star(i))// &
            " is outside its valid range [0, 1/2]")
      end do
      allocate (rows(max(16, 2*size(opts%a_star))))
      n_rows = 0
      do i = 1, size(opts%a_star)
         call states_at(opts%model, params, opts%a_star(i), states)
         n = size(states)
         if (n_rows + n > size(rows)) then
            allocate (grown(2*size(rows) + n))
            grown(1:n_rows) = rows(1:n_rows)
            call move_alloc(grown, rows)
         end if
         rows(n_rows + 1:n_rows + n) = states
         n_rows = n_rows + n
      end do
      call write_header(out, opts%format, "equilibria at given a*", model_name(opts%model), &
         params, "a_star c_star P_star zone_case gbar", &
         [character(len=70) :: "zone_case: 1 a*<c*<1/2, 2 c*=1/2, 3 full contact", &
         "gbar: mean gap over Delta (NaN where not defined)"])
      do i = 1, n_rows
         call write_row(out, opts%format, [rows(i)%a_star, rows(i)%c_star, rows(i)%p_star], &
            [rows(i)%zone_case], tail=[gbar_or_nan(rows(i)%gbar)])
      end do
   end subroutine run_point

   !> All states of a model at one a* (Westergaard and JKR: one, with c* = a*).
   subroutine states_at(model, params, a_star, states)
      integer, intent(in) :: model
      type(params_type), intent(in) :: params
      real(wp), intent(in) :: a_star
      type(state_type), allocatable, intent(inout) :: states(:)
      type(state_type) :: buffer(8)
      type(state_type), allocatable :: big(:)
      character(len=256) :: msg
      integer :: n, status

      msg = ""
      call model_roots(model, params, a_star, buffer, n, status, msg)
      if (status == wa_capacity_too_small .and. n > size(buffer)) then
         allocate (big(n))
         call model_roots(model, params, a_star, big, n, status, msg)
         if (status == wa_ok) states = big(1:n)
      else if (status == wa_ok) then
         states = buffer(1:n)
      end if
      if (status /= wa_ok) call numerical_error(status, "a_star = "//format_real(a_star)// &
         ": "//trim(msg))
   end subroutine states_at

   !> branch: the equilibrium curve by continuation, with its events.
   subroutine run_branch(opts, params)
      type(cli_options), intent(in) :: opts
      type(params_type), intent(in) :: params
      type(branch_type) :: b
      character(len=256) :: msg
      integer :: i, status

      msg = ""
      call trace_branch(opts%model, params, b, status, msg)
      if (status /= wa_ok) call numerical_error(status, msg)
      call write_header(out, opts%format, "equilibrium branch (pseudo-arclength continuation)", &
         model_name(opts%model), params, &
         "a_star c_star P_star b_star zone_case stable event gbar", &
         [character(len=80) :: "b_star = a* + 0.4 (c* - a*); stable: 1 = stable under load control", &
         event_legend(1), event_legend(2), event_legend(3), &
         "zone_case: 0 no contact (MD: a* = 0, Dugdale zone |x*| < c*), 1 a*<c*<1/2,", &
         "           2 c*=1/2, 3 full contact", "gbar: mean gap over Delta"])
      do i = 1, b%n
         call write_row(out, opts%format, [b%a_star(i), b%c_star(i), b%p_star(i), &
            b%a_star(i) + 0.4_wp*(b%c_star(i) - b%a_star(i))], &
            [b%zone_case(i), merge(1, 0, b%stable(i)), b%event(i)], tail=[gbar_or_nan(b%gbar(i))])
      end do
   end subroutine run_branch

   !> The mean gap as printed: NaN where it is not defined (e.g. DW at a* = 0).
   elemental real(wp) function gbar_or_nan(g)
      real(wp), intent(in) :: g
      gbar_or_nan = g
      if (.not. (g >= 0.0_wp .and. g <= huge(g))) gbar_or_nan = ieee_value(g, ieee_quiet_nan)
   end function gbar_or_nan

   !> profile: traction and gap of one state at --n points x* from -1/2 to 1/2.
   subroutine run_profile(opts, params)
      type(cli_options), intent(in) :: opts
      type(params_type), intent(in) :: params
      real(wp), allocatable :: x(:), traction(:), gap(:)
      type(state_type) :: state
      character(len=256) :: msg
      character(len=60) :: which
      character(len=100) :: notes(5)
      real(wp) :: a_star, c_star
      integer :: i, n, status

      if (.not. allocated(opts%a_star)) call usage_error("profile needs --a-star X")
      a_star = single(opts%a_star, "--a-star")
      if (.not. (a_star >= 0.0_wp .and. a_star <= 0.5_wp)) call usage_error("--a-star: "// &
         format_real(a_star)//" is outside its valid range [0, 1/2]")
      n = opts%n_points
      allocate (x(n), traction(n), gap(n))
      do i = 1, n
         x(i) = -0.5_wp + real(i - 1, wp)/real(n - 1, wp)
      end do
      msg = ""
      if (allocated(opts%c_star)) then
         c_star = single(opts%c_star, "--c-star")
         call model_profile(opts%model, params, a_star, x, traction, gap, state, status, msg, &
            c_star)
         which = "the state with c* nearest --c-star"
      else
         call model_profile(opts%model, params, a_star, x, traction, gap, state, status, msg)
         which = "the principal state"
      end if
      if (status == wa_invalid_argument) call usage_error(option_message(trim(msg)))
      if (status /= wa_ok) call numerical_error(status, trim(msg))
      notes(1) = "state: "//which
      notes(2) = "a_star = "//format_real(state%a_star)//"  c_star = "// &
         format_real(state%c_star)
      notes(3) = "P_star = "//format_real(state%p_star)//"  zone_case = "// &
         zone_text(state%zone_case)
      notes(4) = "gbar = "//format_real(gbar_or_nan(state%gbar))//" (mean gap over Delta)"
      notes(5) = "traction: p/p* (positive = compressive); gap: h/Delta (0 on the contact)"
      call write_header(out, opts%format, "traction and gap profiles of one state", &
         model_name(opts%model), params, "x_star traction gap", notes)
      do i = 1, n
         call write_row(out, opts%format, [x(i), traction(i), gap(i)])
      end do
   end subroutine run_profile

   !> "1 (a*<c*<1/2)" and so on.
   function zone_text(zone) result(text)
      integer, intent(in) :: zone
      character(len=:), allocatable :: text
      select case (zone)
      case (0); text = "0 (no contact: Dugdale zone |x*| < c*)"
      case (1); text = "1 (a* < c* < 1/2)"
      case (2); text = "2 (c* = 1/2)"
      case default; text = "3 (full contact)"
      end select
   end function zone_text

   !> path: the events of loading (stage 1) and unloading (stage 2).
   subroutine run_path(opts, params)
      type(cli_options), intent(in) :: opts
      type(params_type), intent(in) :: params
      type(path_type) :: path
      type(branch_type) :: branch
      character(len=256) :: msg
      character(len=160), allocatable :: notes(:)
      real(wp) :: energy(64)
      integer :: i, status

      msg = ""
      call trace_branch(opts%model, params, branch, status, msg)
      if (status /= wa_ok) call numerical_error(status, msg)
      call path_from_branch(opts%model, params, branch, path, status, msg)
      if (status /= wa_ok) call numerical_error(status, msg)
      call load_jump_energies(opts%model, params, branch, path, energy, status, msg)
      if (status /= wa_ok) call numerical_error(status, msg)
      notes = [character(len=160) :: "stage: 1 loading, 2 unloading", event_legend(1), &
         event_legend(2), "P_fc = "//format_real(path%p_fc)//"  P_pf = "// &
         format_real(path%p_pf), "energy released by each jump (units p* Delta per period):"]
      do i = 1, path%n
         if (path%event(i) /= event_jump_start) cycle
         if (energy(i) == energy(i)) then
            notes = [character(len=160) :: notes, "  jump starting at event row "//int_text(i)// &
               ", P* = "//format_real(path%p_star(i))//": "//format_real(energy(i))]
         else                    ! NaN: the separated state is not on the branch
            notes = [character(len=160) :: notes, "  jump starting at event row "//int_text(i)// &
               ", P* = "//format_real(path%p_star(i))//": not defined", &
               "    (it leaves or lands on separated surfaces: a pull-off or a jump-in)"]
         end if
      end do
      notes = [character(len=160) :: notes, "P-a loop area (the paper's measure, not an "// &
         "energy) = "//format_real(path%loop_area)]
      call write_header(out, opts%format, "load-controlled loading and unloading", &
         model_name(opts%model), params, "stage event a_star c_star P_star", notes)
      do i = 1, path%n
         call write_row_ints_first(out, opts%format, [path%stage(i), path%event(i)], &
            [path%a_star(i), path%c_star(i), path%p_star(i)])
      end do
   end subroutine run_path

   !> path --control gap: approach and retraction under mean-gap control.
   subroutine run_gap_path(opts, params)
      type(cli_options), intent(in) :: opts
      type(params_type), intent(in) :: params
      type(gap_path_type) :: path
      character(len=256) :: msg
      integer :: i, status

      msg = ""
      call gap_path(opts%model, params, path, status, msg)
      if (status /= wa_ok) call numerical_error(status, msg)
      call write_header(out, opts%format, "gap-controlled approach and retraction", &
         model_name(opts%model), params, "stage event a_star c_star P_star gbar", &
         [character(len=80) :: "stage: 1 approach (gbar* falling), 2 retraction (rising)", &
         "event: 3 jump start, 4 jump end (at constant gbar*), 5 full contact reached,", &
         "       6 full contact left, 10 first interaction (touch), 11 contact made,", &
         "       12 contact lost, 13 interaction lost (P* = 0 beyond)", &
         "energy lost per cycle W* = -oint P* dgbar* (units p* Delta):", &
         "W* = "//format_real(path%w_star)//"  W*/(pi alpha^2/2) = "// &
         format_real(path%w_fraction)])
      do i = 1, path%n
         call write_row_ints_first(out, opts%format, [path%stage(i), path%event(i)], &
            [path%a_star(i), path%c_star(i), path%p_star(i), path%gbar(i)])
      end do
   end subroutine run_gap_path

   !> gaplaw: P* on approach and retraction and their slopes on a uniform gbar* grid.
   subroutine run_gaplaw(opts, params)
      type(cli_options), intent(in) :: opts
      type(params_type), intent(in) :: params
      real(wp), allocatable :: pa(:), pr(:), da(:), dr(:)
      character(len=256) :: msg
      integer :: i, n, status

      n = size(opts%gbar)
      allocate (pa(n), pr(n), da(n), dr(n))
      msg = ""
      call gap_law(opts%model, params, opts%gbar, pa, pr, da, dr, status, msg)
      if (status /= wa_ok) call numerical_error(status, msg)
      call write_header(out, opts%format, "gap law: P* against the mean gap gbar* (gap control)", &
         model_name(opts%model), params, "gbar P_approach P_retract dPdg_approach dPdg_retract", &
         [character(len=80) :: "P_approach: after approaching from far apart; P_retract: after", &
         "retracting from full contact (doc/user-guide.md, hysteresis convention);", &
         "P* = 0 and slope 0 where the surfaces do not interact"])
      do i = 1, n
         call write_row(out, opts%format, [opts%gbar(i), pa(i), pr(i), da(i), dr(i)])
      end do
   end subroutine run_gaplaw

   !> critical: P_fc and P_pf over alpha x mu. A failing (alpha, mu) never loses the
   !> table: its row is written with NaN forces, standard error names it and its reason,
   !> and rows_failed makes the exit status 1 once the whole table is written.
   subroutine run_critical(opts, si_params, rows_failed)
      type(cli_options), intent(in) :: opts
      !> alpha and mu from the SI options (when given)
      type(params_type), intent(in) :: si_params
      logical, intent(out) :: rows_failed
      real(wp), allocatable :: alpha(:), mu(:), p_fc(:, :), p_pf(:, :)
      integer, allocatable :: fc_mech(:, :), pf_mech(:, :), row_stat(:)
      character(len=256), allocatable :: row_msg(:)
      character(len=256) :: msg
      type(params_type) :: params
      integer :: i, j, status, n_failed
      real(wp) :: t0, t1
      logical :: progress

      call critical_grid(opts, si_params, alpha, mu)
      msg = ""
      allocate (p_fc(size(mu), size(alpha)), p_pf(size(mu), size(alpha)), &
         fc_mech(size(mu), size(alpha)), pf_mech(size(mu), size(alpha)), &
         row_stat(size(mu)), row_msg(size(mu)))
      call cpu_time(t0)
      progress = .false.
      n_failed = 0
      do j = 1, size(alpha)
         call critical_sweep(opts%model, alpha(j), mu, p_fc(:, j), p_pf(:, j), fc_mech(:, j), &
            pf_mech(:, j), status, msg, row_stat, row_msg)
         do i = 1, size(mu)
            if (row_stat(i) == wa_ok) cycle
            n_failed = n_failed + 1
            write (error_unit, '(a)') "wavyadhesion: critical: alpha = "// &
               format_real(alpha(j))//", mu = "//format_real(mu(i))//": "// &
               status_message(row_stat(i))//": "//trim(row_msg(i))// &
               " (row written with NaN forces)"
         end do
         call cpu_time(t1)
         if (t1 - t0 > 1.0_wp .and. isatty(error_unit)) progress = .true.
         if (progress) write (error_unit, '(a,i0,a,i0)') "critical: alpha ", j, " of ", size(alpha)
      end do
      rows_failed = n_failed > 0
      call write_header(out, opts%format, "critical forces (full contact, pull-off)", &
         model_name(opts%model), columns="alpha mu P_fc P_pf", notes=[character(len=400) :: &
         "P_fc: load at which full contact is first reached (loading from P* = 0)", &
         "P_pf: pull-off load on unloading from full contact (-Infinity: never)", &
         failure_note(n_failed, size(p_fc)), &
         mechanism_notes(opts, alpha, mu, fc_mech, pf_mech)])
      do j = 1, size(alpha)
         do i = 1, size(mu)
            call write_row(out, opts%format, [alpha(j), mu(i), p_fc(i, j), p_pf(i, j)])
         end do
      end do
      if (rows_failed) write (error_unit, '(a,i0,a,i0,a)') "wavyadhesion: critical: ", &
         n_failed, " of ", size(p_fc), " rows failed (written with NaN forces); exit status 1"
   end subroutine run_critical

   !> critical --control gap: the critical values of mean-gap control over alpha x mu
   !> (gap_critical_sweep); failing rows as in run_critical (NaN, reason on stderr).
   subroutine run_gap_critical(opts, si_params, rows_failed)
      type(cli_options), intent(in) :: opts
      !> alpha and mu from the SI options (when given)
      type(params_type), intent(in) :: si_params
      logical, intent(out) :: rows_failed
      real(wp), allocatable :: alpha(:), mu(:), values(:, :, :)
      integer, allocatable :: row_stat(:)
      character(len=256), allocatable :: row_msg(:)
      character(len=256) :: msg
      character(len=24) :: t_fail, t_all
      character(len=400), allocatable :: notes(:)
      type(params_type) :: params
      integer :: i, j, status, n_failed

      call critical_grid(opts, si_params, alpha, mu)
      msg = ""
      allocate (values(gap_critical_count, size(mu), size(alpha)), row_stat(size(mu)), &
         row_msg(size(mu)))
      n_failed = 0
      do j = 1, size(alpha)
         call gap_critical_sweep(opts%model, alpha(j), mu, values(:, :, j), status, msg, &
            row_stat, row_msg)
         do i = 1, size(mu)
            if (row_stat(i) == wa_ok) cycle
            n_failed = n_failed + 1
            write (error_unit, '(a)') "wavyadhesion: critical: alpha = "// &
               format_real(alpha(j))//", mu = "//format_real(mu(i))//": "// &
               status_message(row_stat(i))//": "//trim(row_msg(i))// &
               " (row written with NaN values)"
         end do
      end do
      rows_failed = n_failed > 0
      write (t_fail, '(i0)') n_failed
      write (t_all, '(i0)') size(mu)*size(alpha)
      notes = [character(len=400) :: &
         "g_touch: gbar* where the approach first feels the surface (P* = 0 above)", &
         "P_jump_in, a_jump_in: P* and a* where the approach lands when it jumps at", &
         "  g_touch (a jump keeps gbar*); 0 and 0: no jump (P* leaves 0 gradually)", &
         "g_contact: gbar* where contact is first made on the approach", &
         "P_min, g_P_min, a_P_min: the most tensile load on the retraction and its", &
         "  gbar* and a* (jkr: -Infinity at full contact)", &
         "g_contact_lost, P_contact_lost: gbar* where contact is lost for good on the", &
         "  retraction and P* of the last state with contact", &
         "g_interaction_lost: gbar* beyond which P* = 0 on the retraction"]
      if (n_failed > 0) notes = [character(len=400) :: notes, trim(t_fail)//" of "// &
         trim(t_all)//" rows failed: their values are NaN (reasons on standard error)"]
      call write_header(out, opts%format, "critical values under mean-gap control "// &
         "(approach, retraction)", model_name(opts%model), &
         columns="alpha mu "//gap_critical_names, notes=notes)
      do j = 1, size(alpha)
         do i = 1, size(mu)
            call write_row(out, opts%format, [alpha(j), mu(i), values(:, i, j)])
         end do
      end do
      if (rows_failed) write (error_unit, '(a,i0,a,i0,a)') "wavyadhesion: critical: ", &
         n_failed, " of ", size(mu)*size(alpha), " rows failed (written with NaN values); "// &
         "exit status 1"
   end subroutine run_gap_critical

   !> map: the boundary curves of the adhesion map, rows "boundary alpha mu" (boundary:
   !> the integer code, meanings in the header), each curve in increasing alpha.
   subroutine run_map(opts)
      type(cli_options), intent(in) :: opts
      real(wp), allocatable :: alpha(:), mu(:)
      type(map_type) :: map
      character(len=256) :: msg
      character(len=400), allocatable :: notes(:)
      character(len=*), parameter :: ends(0:3) = [character(len=24) :: "grid edge", &
         "inside (meets/turns)", "leaves the mu range", "load path fails"]
      integer :: status, c, i, k, control
      logical :: seen

      control = map_control_load
      if (allocated(opts%control)) then
         if (opts%control == "gap") control = map_control_gap
         if (opts%control == "both") control = map_control_both
      end if
      alpha = [(10.0_wp**(-2.0_wp + 3.0_wp*real(i - 1, wp)/199.0_wp), i = 1, 200)]
      mu = [1.0e-3_wp, 1.0e3_wp]
      if (allocated(opts%alpha)) alpha = opts%alpha
      if (allocated(opts%mu)) mu = opts%mu
      if (opts%model /= model_dw .and. opts%model /= model_md) &
         call usage_error("map: --model must be dw or md (westergaard and jkr have one "// &
         "mechanism each)")
      if (size(mu) < 2) call usage_error("map: --mu-range needs N >= 2")
      msg = ""
      call adhesion_map(opts%model, alpha, mu(1), mu(size(mu)), max(size(mu), 60), map, &
         status, msg, control=control)
      if (status == wa_invalid_argument) call usage_error("map: "//trim(msg))
      if (status /= wa_ok) call numerical_error(status, msg)
      allocate (notes(0))
      do c = 1, map%n_boundaries
         seen = .false.
         do k = 1, c - 1
            seen = seen .or. map%boundary(k)%code == map%boundary(c)%code
         end do
         if (.not. seen) notes = [character(len=400) :: notes, "boundary "// &
            int_text(map%boundary(c)%code)//" = "//boundary_meaning(map%boundary(c)%code)]
      end do
      notes = [character(len=400) :: notes, &
         "boundary code = 100*which + 10*(mechanism below) + (mechanism above) in mu;", &
         "which 1 full contact, 2 pull-off (load control): mechanism 0 gradual, 1 jump "// &
         "case 1, 2 jump case 2, 3 snap at P=0;", &
         "which 3 approach, 4 retraction (gap control, --control gap|both): mechanism "// &
         "1 (flag) contact made/lost by a jump,", &
         "  2 (flag) jump(s) between states with contact (approach: at gbar* minima; "// &
         "retraction: before contact is lost)", &
         "each point located to 2e-9 relative in mu"]
      do c = 1, map%n_boundaries
         associate (b => map%boundary(c))
            notes = [character(len=400) :: notes, "curve "//int_text(c)//" ("// &
               int_text(b%code)//"): starts alpha "//format_real(b%alpha(1))//" mu "// &
               format_real(b%mu(1))//" ["//trim(ends(b%start_kind))//"], ends alpha "// &
               format_real(b%alpha(b%n))//" mu "//format_real(b%mu(b%n))//" ["// &
               trim(ends(b%end_kind))//"]"]
         end associate
      end do
      do c = 1, map%n_special
         notes = [character(len=400) :: notes, "special point "//int_text(c)//": alpha "// &
            format_real(map%special(c)%alpha)//" mu "//format_real(map%special(c)%mu)// &
            ": "//special_meaning(map%special(c))]
      end do
      call write_header(out, opts%format, "adhesion map: mechanism boundaries mu_b(alpha)", &
         model_name(opts%model), columns="boundary alpha mu", notes=notes)
      do c = 1, map%n_boundaries
         do i = 1, map%boundary(c)%n
            call write_row_ints_first(out, opts%format, [map%boundary(c)%code], &
               [map%boundary(c)%alpha(i), map%boundary(c)%mu(i)])
         end do
      end do
   end subroutine run_map

   pure function int_text(i) result(text)
      integer, intent(in) :: i
      character(len=:), allocatable :: text
      character(len=12) :: buf
      write (buf, '(i0)') i
      text = trim(buf)
   end function int_text

   !> A header line saying how many rows failed (none when every row succeeded).
   function failure_note(n_failed, n_rows) result(notes)
      integer, intent(in) :: n_failed, n_rows
      character(len=400), allocatable :: notes(:)
      character(len=24) :: a, b
      allocate (notes(0))
      if (n_failed == 0) return
      write (a, '(i0)') n_failed
      write (b, '(i0)') n_rows
      notes = [character(len=400) :: trim(a)//" of "//trim(b)//" rows failed: their P_fc "// &
         "and P_pf are NaN (reasons on standard error)"]
   end function failure_note

   !> Header lines locating in mu each change of mechanism (table format only), between
   !> consecutive rows that succeeded. A change that cannot be located to 1e-10 (the load
   !> path fails inside the bracket) is given as the interval known to hold it.
   function mechanism_notes(opts, alpha, mu, fc_mech, pf_mech) result(notes)
      type(cli_options), intent(in) :: opts
      real(wp), intent(in) :: alpha(:), mu(:)
      integer, intent(in) :: fc_mech(:, :), pf_mech(:, :)
      character(len=400), allocatable :: notes(:)
      character(len=*), parameter :: names(0:3) = [character(len=12) :: "gradual", &
         "jump case 1", "jump case 2", "snap at P=0"]
      character(len=256) :: msg
      character(len=:), allocatable :: where, change
      real(wp) :: mu_c, bracket(2)
      integer :: i, k, j, which, status, m(2)
      allocate (notes(0))
      if (opts%format == "csv") return
      do j = 1, size(alpha)
         i = next_good(fc_mech(:, j), 0)
         do while (i > 0)
            k = next_good(fc_mech(:, j), i)
            if (k == 0) exit
            do which = 1, 2
               if (which == 1) m = [fc_mech(i, j), fc_mech(k, j)]
               if (which == 2) m = [pf_mech(i, j), pf_mech(k, j)]
               if (m(1) == m(2)) cycle
               msg = ""
               call mechanism_change(opts%model, alpha(j), which, mu(i), mu(k), mu_c, status, &
                  msg, bracket)
               change = merge(" P_fc: ", " P_pf: ", which == 1)//trim(names(m(1)))//" -> "// &
                  trim(names(m(2)))
               if (status == wa_ok) then
                  where = " mu "//format_real(mu_c)
               else
                  where = " mu in ["//format_real(bracket(1))//", "//format_real(bracket(2))//"]"
                  write (error_unit, '(a)') "wavyadhesion: critical: alpha = "// &
                     format_real(alpha(j))//":"//where//change//": "//trim(msg)
                  change = change//" (not located further: the load path fails there)"
               end if
               notes = [character(len=400) :: notes, "alpha "//format_real(alpha(j))//where// &
                  change]
            end do
            i = k
         end do
      end do
   end function mechanism_notes

   !> The next row after i whose forces were computed (mechanism >= 0), 0 when none.
   pure integer function next_good(mechanism, i)
      integer, intent(in) :: mechanism(:), i
      integer :: r
      next_good = 0
      do r = i + 1, size(mechanism)
         if (mechanism(r) >= 0) then
            next_good = r
            return
         end if
      end do
   end function next_good

   !> The alpha and mu of `critical` (both controls): defaults 0.3 and 1, the SI options,
   !> then --alpha and --mu / --mu-range; every value checked before any work.
   subroutine critical_grid(opts, si_params, alpha, mu)
      type(cli_options), intent(in) :: opts
      type(params_type), intent(in) :: si_params
      real(wp), allocatable, intent(out) :: alpha(:), mu(:)
      type(params_type) :: params
      character(len=256) :: msg
      integer :: i, status
      alpha = [0.3_wp]
      mu = [1.0_wp]
      if (si_given(opts)) then
         alpha = [si_params%alpha]
         mu = [si_params%mu]
      end if
      if (allocated(opts%alpha)) alpha = opts%alpha
      if (allocated(opts%mu)) mu = opts%mu
      msg = ""
      do i = 1, size(alpha)
         call new_params(alpha(i), 1.0_wp, params, status, msg)
         if (status /= wa_ok) call usage_error(option_message(trim(msg)))
      end do
      do i = 1, size(mu)
         call new_params(1.0_wp, mu(i), params, status, msg)
         if (status /= wa_ok) call usage_error(option_message(trim(msg)))
      end do
   end subroutine critical_grid

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

   !> A path row: stage and event first, then the reals (same separators as write_row).
   subroutine write_row_ints_first(out, format, ints, reals)
      type(sink_type), intent(inout) :: out
      character(len=*), intent(in) :: format
      integer, intent(in) :: ints(:)
      real(wp), intent(in) :: reals(:)
      character(len=1) :: sep
      character(len=32) :: head
      sep = merge(",", " ", format == "csv")
      write (head, '(i0)') ints(1)
      if (size(ints) > 1) write (head, '(i0,a,i0)') ints(1), sep, ints(2)
      call write_row(out, format, reals, prefix=trim(head)//sep)
   end subroutine write_row_ints_first

   subroutine usage_error(message)
      character(len=*), intent(in) :: message
      call discard_sink(out)
      write (error_unit, '(a)') "wavyadhesion: "//message
      write (error_unit, '(a)') "Try 'wavyadhesion --help'."
      stop 2, quiet=.true.
   end subroutine usage_error

   subroutine numerical_error(status, message)
      integer, intent(in) :: status
      character(len=*), intent(in) :: message
      call discard_sink(out)
      write (error_unit, '(a)') "wavyadhesion: "//status_message(status)//": "//trim(message)// &
         " (no table written)"
      stop 1, quiet=.true.
   end subroutine numerical_error

   subroutine print_help()
      integer :: i
      character(len=100), parameter :: text(52) = [character(len=100) :: &
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
         "  profile   traction and gap of one state over x* in [-1/2, 1/2]: --a-star X", &
         "            [--c-star C] (default: the principal state) [--n N] (default 201)", &
         "  path      loading and unloading under load control: jumps, full contact,", &
         "            pull-off; --control gap: approach and retraction under mean-gap", &
         "            control (jumps, contact made/lost, energy lost per cycle W*)", &
         "  gaplaw    P* on approach and retraction and dP*/dgbar* on a uniform grid of", &
         "            mean gaps: --gbar-range LO:HI:N", &
         "  critical  P_fc and P_pf over --alpha A[,A...] and --mu U[,U...] or", &
         "            --mu-range LO:HI:N[:log] (--control gap: those of mean-gap control)", &
         "  map       adhesion map (dw, md): boundaries between mechanisms as rows", &
         "            'boundary alpha mu' (--alpha-range, default 0.01:10:200:log;", &
         "            --mu-range, default 1e-3:1e3:60:log); --control gap|both: the", &
         "            boundaries under mean-gap control (codes 3xx approach, 4xx", &
         "            retraction) instead of / with the load-control ones", &
         "", &
         "Options:", &
         "  --model M          westergaard | jkr | dw | md (default dw)", &
         "  --alpha A          Johnson's parameter, in [1e-12, 1e12] (default 0.3)", &
         "  --mu U             transition parameter, 0 or in [1e-100, 1e100] (default 1)", &
         "  --mu-range LO:HI:N[:log]", &
         "                     N values of mu from LO to HI (critical, map; not with --mu)", &
         "  --alpha-range LO:HI:N[:log]", &
         "                     N values of alpha (map only; not with --alpha)", &
         "  --a-star X[,X...]  contact half-widths over the period, in [0, 1/2] (point;", &
         "                     profile: one value)", &
         "  --c-star C         profile: c* of the state (within 1e-6; md at a* = 0: the", &
         "                     Dugdale zone half-width of a state without contact)", &
         "  --n N              profile: number of points, in [2, 100000] (default 201)", &
         "  --control C        load (default) | gap (path, critical, map) | both (map)", &
         "  --gbar-range LO:HI:N  mean gaps gbar* >= 0 (gaplaw)", &
         "  --format F         table (default, # comments + numeric rows) | csv", &
         "  --output FILE      write the table to FILE instead of standard output; FILE is", &
         "                     replaced only once the whole table is written", &
         "  --help, --version", &
         "SI input instead of --alpha/--mu/--mu-range (the whole set, not mixed):", &
         "  --Estar, or all of --E1 --nu1 --E2 --nu2 [Pa], --period --amplitude [m],", &
         "  --work-of-adhesion [J/m^2], --peak-stress [Pa]", &
         "", &
         "Numbers are decimal (0.3, -1, 2.5e-3); each option may be given once.", &
         "Exit status: 0 ok; 2 usage error; 1 numerical failure or write error. No table", &
         "is written on failure, except by critical, which writes every row (NaN where a", &
         "row failed, named on standard error) and then exits with 1."]
      do i = 1, size(text)
         call put_line(out, trim(text(i)))
      end do
   end subroutine print_help

end program wavyadhesion_cli
