!> The CLI's state subcommands: `point` (every equilibrium at given a*), `branch` (the
!> equilibrium curve by continuation) and `profile` (traction and gap of one state).
module wa_cli_states
   use wa_kinds, only: wp
   use wavyadhesion, only: params_type, state_type, branch_type, model_roots, trace_branch, &
      model_profile, wa_ok, wa_capacity_too_small, wa_invalid_argument
   use wa_cli_options, only: cli_options, model_name, option_message
   use wa_cli_table, only: table_type, add_value, write_header, write_row, format_real
   use wa_cli_progress, only: progress_type, progress_start, progress_step, progress_end
   use wa_cli_common, only: usage_error, numerical_error, single, gbar_or_nan, event_legend
   implicit none
   private

   public :: run_point, run_branch, run_profile

contains

   !> point: every equilibrium at each a*. Linear in the number of a*: the rows are kept
   !> in an array that doubles when full.
   subroutine run_point(opts, params, tab)
      type(cli_options), intent(in) :: opts
      type(params_type), intent(in) :: params
      type(table_type), intent(inout) :: tab
      type(state_type), allocatable :: rows(:), grown(:), states(:)
      type(progress_type) :: progress
      integer :: i, n_rows, n

      if (.not. allocated(opts%a_star)) call usage_error(tab, "point needs --a-star X[,X...]")
      do i = 1, size(opts%a_star)
         if (.not. (opts%a_star(i) >= 0.0_wp .and. opts%a_star(i) <= 0.5_wp)) &
            call usage_error(tab, "--a-star: "//format_real(opts%a_star(i))// &
            " is outside its valid range [0, 1/2]")
      end do
      allocate (rows(max(16, 2*size(opts%a_star))))
      n_rows = 0
      call progress_start(progress, "point")
      do i = 1, size(opts%a_star)
         call progress_step(progress, i - 1, size(opts%a_star))
         call states_at(tab, opts%model, params, opts%a_star(i), states)
         n = size(states)
         if (n_rows + n > size(rows)) then
            allocate (grown(2*size(rows) + n))
            grown(1:n_rows) = rows(1:n_rows)
            call move_alloc(grown, rows)
         end if
         rows(n_rows + 1:n_rows + n) = states
         n_rows = n_rows + n
      end do
      call progress_end(progress)
      call write_header(tab, "equilibria at given a*", model_name(opts%model), &
         "a_star c_star P_star zone_case gbar", params, &
         [character(len=70) :: "zone_case: 1 a*<c*<1/2, 2 c*=1/2, 3 full contact", &
         "gbar: mean gap over Delta (NaN where not defined)"])
      do i = 1, n_rows
         call write_row(tab, [rows(i)%a_star, rows(i)%c_star, rows(i)%p_star, &
            real(rows(i)%zone_case, wp), gbar_or_nan(rows(i)%gbar)])
      end do
   end subroutine run_point

   !> All states of a model at one a* (Westergaard and JKR: one, with c* = a*).
   subroutine states_at(tab, model, params, a_star, states)
      type(table_type), intent(inout) :: tab
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
      if (status /= wa_ok) call numerical_error(tab, status, "a_star = "//format_real(a_star)// &
         ": "//trim(msg))
   end subroutine states_at

   !> branch: the equilibrium curve by continuation, with its events.
   subroutine run_branch(opts, params, tab)
      type(cli_options), intent(in) :: opts
      type(params_type), intent(in) :: params
      type(table_type), intent(inout) :: tab
      type(branch_type) :: b
      character(len=256) :: msg
      integer :: i, status

      msg = ""
      call trace_branch(opts%model, params, b, status, msg)
      if (status /= wa_ok) call numerical_error(tab, status, msg)
      call write_header(tab, "equilibrium branch (pseudo-arclength continuation)", &
         model_name(opts%model), "a_star c_star P_star b_star zone_case stable event gbar", &
         params, [character(len=80) :: &
         "b_star = a* + 0.4 (c* - a*); stable: 1 = stable under load control", &
         event_legend(1), event_legend(2), event_legend(3), &
         "zone_case: 0 no contact (MD: a* = 0, Dugdale zone |x*| < c*), 1 a*<c*<1/2,", &
         "           2 c*=1/2, 3 full contact", "gbar: mean gap over Delta"])
      do i = 1, b%n
         call write_row(tab, [b%a_star(i), b%c_star(i), b%p_star(i), &
            b%a_star(i) + 0.4_wp*(b%c_star(i) - b%a_star(i)), real(b%zone_case(i), wp), &
            merge(1.0_wp, 0.0_wp, b%stable(i)), real(b%event(i), wp), gbar_or_nan(b%gbar(i))])
      end do
   end subroutine run_branch

   !> profile: traction and gap of one state at --n points x* from -1/2 to 1/2.
   subroutine run_profile(opts, params, tab)
      type(cli_options), intent(in) :: opts
      type(params_type), intent(in) :: params
      type(table_type), intent(inout) :: tab
      real(wp), allocatable :: x(:), traction(:), gap(:)
      type(state_type) :: state
      character(len=256) :: msg
      character(len=60) :: which
      character(len=100) :: notes(5)
      real(wp) :: a_star, c_star
      integer :: i, n, status

      if (.not. allocated(opts%a_star)) call usage_error(tab, "profile needs --a-star X")
      a_star = single(tab, opts%a_star, "--a-star")
      if (.not. (a_star >= 0.0_wp .and. a_star <= 0.5_wp)) call usage_error(tab, "--a-star: "// &
         format_real(a_star)//" is outside its valid range [0, 1/2]")
      n = opts%n_points
      allocate (x(n), traction(n), gap(n))
      do i = 1, n
         x(i) = -0.5_wp + real(i - 1, wp)/real(n - 1, wp)
      end do
      msg = ""
      if (allocated(opts%c_star)) then
         c_star = single(tab, opts%c_star, "--c-star")
         call model_profile(opts%model, params, a_star, x, traction, gap, state, status, msg, &
            c_star)
         which = "the state with c* nearest --c-star"
      else
         call model_profile(opts%model, params, a_star, x, traction, gap, state, status, msg)
         which = "the principal state"
      end if
      if (status == wa_invalid_argument) call usage_error(tab, option_message(trim(msg)))
      if (status /= wa_ok) call numerical_error(tab, status, trim(msg))
      notes(1) = "state: "//which
      notes(2) = "a_star = "//format_real(state%a_star)//"  c_star = "// &
         format_real(state%c_star)
      notes(3) = "P_star = "//format_real(state%p_star)//"  zone_case = "// &
         zone_text(state%zone_case)
      notes(4) = "gbar = "//format_real(gbar_or_nan(state%gbar))//" (mean gap over Delta)"
      notes(5) = "traction: p/p* (positive = compressive); gap: h/Delta (0 on the contact)"
      call add_value(tab, "a_star", [state%a_star])
      call add_value(tab, "c_star", [state%c_star])
      call add_value(tab, "P_star", [state%p_star])
      call add_value(tab, "zone_case", [real(state%zone_case, wp)], integers=.true.)
      call add_value(tab, "gbar", [gbar_or_nan(state%gbar)])
      call write_header(tab, "traction and gap profiles of one state", &
         model_name(opts%model), "x_star traction gap", params, notes)
      do i = 1, n
         call write_row(tab, [x(i), traction(i), gap(i)])
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

end module wa_cli_states
