!> What the CLI's drivers share: the two ways a run fails (usage error, exit status 2;
!> numerical failure, exit status 1; both discard the table), the model parameters from
!> the options, and small pieces of the table headers.
module wa_cli_common
   use, intrinsic :: iso_fortran_env, only: error_unit
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
   use wa_kinds, only: wp
   use wavyadhesion, only: params_type, scales_type, new_params, dimensional_params, &
      reduced_modulus, status_message, wa_ok
   use wa_cli_options, only: cli_options, given, si_given, option_message
   use wa_cli_table, only: table_type, discard_table
   use wa_cli_units, only: si_scales_type
   implicit none
   private

   public :: usage_error, numerical_error, resolve_params, single, gbar_or_nan, event_legend

contains

   !> Print the message and "Try 'wavyadhesion --help'." and exit with status 2.
   subroutine usage_error(tab, message)
      type(table_type), intent(inout) :: tab
      character(len=*), intent(in) :: message
      call discard_table(tab)
      write (error_unit, '(a)') "wavyadhesion: "//message
      write (error_unit, '(a)') "Try 'wavyadhesion --help'."
      stop 2, quiet=.true.
   end subroutine usage_error

   !> Print the library's status and message and exit with status 1 (no table written).
   subroutine numerical_error(tab, status, message)
      type(table_type), intent(inout) :: tab
      integer, intent(in) :: status
      character(len=*), intent(in) :: message
      call discard_table(tab)
      write (error_unit, '(a)') "wavyadhesion: "//status_message(status)//": "//trim(message)// &
         " (no table written)"
      stop 1, quiet=.true.
   end subroutine numerical_error

   !> alpha, mu from --alpha/--mu (defaults 0.3, 1) or from the SI options (the parser
   !> has checked that the SI set is complete and not mixed with --alpha/--mu), with
   !> their SI scales (si%given = .false. without SI input).
   subroutine resolve_params(tab, opts, params, si)
      type(table_type), intent(inout) :: tab
      type(cli_options), intent(in) :: opts
      type(params_type), intent(out) :: params
      type(si_scales_type), intent(out) :: si
      type(scales_type) :: scales
      character(len=256) :: msg
      real(wp) :: alpha, mu, estar
      integer :: status

      msg = ""
      if (si_given(opts)) then
         estar = opts%estar
         if (.not. given(opts, "--Estar")) then
            call reduced_modulus(opts%e1, opts%nu1, opts%e2, opts%nu2, estar, status, msg)
            if (status /= wa_ok) call usage_error(tab, "--E1/--nu1/--E2/--nu2: "// &
               option_message(trim(msg)))
         end if
         call dimensional_params(estar, opts%period, opts%amplitude, opts%work, opts%peak, &
            params, scales, status, msg)
         if (status /= wa_ok) call usage_error(tab, option_message(trim(msg)))
         si = si_scales_type(given=.true., estar=estar, pressure=scales%pressure, &
            force=scales%force, length=scales%length, delta=opts%amplitude, &
            energy=scales%pressure*opts%amplitude)
         return
      end if
      alpha = 0.3_wp
      mu = 1.0_wp
      if (allocated(opts%alpha)) alpha = single(tab, opts%alpha, "--alpha")
      if (allocated(opts%mu)) mu = single(tab, opts%mu, "--mu")
      call new_params(alpha, mu, params, status, msg)
      if (status /= wa_ok) call usage_error(tab, option_message(trim(msg)))
   end subroutine resolve_params

   !> The one value of a list option (a usage error when it has more).
   real(wp) function single(tab, values, name)
      type(table_type), intent(inout) :: tab
      real(wp), intent(in) :: values(:)
      character(len=*), intent(in) :: name
      if (size(values) /= 1) call usage_error(tab, name//" takes one value for this subcommand")
      single = values(1)
   end function single

   !> The mean gap as printed: NaN where it is not defined (e.g. DW at a* = 0).
   elemental real(wp) function gbar_or_nan(g)
      real(wp), intent(in) :: g
      gbar_or_nan = g
      if (.not. (g >= 0.0_wp .and. g <= huge(g))) gbar_or_nan = ieee_value(g, ieee_quiet_nan)
   end function gbar_or_nan

   !> The three header lines that explain the event codes of branch and path.
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

end module wa_cli_common
