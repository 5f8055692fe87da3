!> SI units for the CLI's output (`--units si`, with SI input): the scales that turn the
!> dimensionless columns into physical ones, and which column takes which scale.
!> Widths a* = a/L, loads P* = mean traction/p*, gaps gbar* = gbar/Delta, energies per
!> area W* in units of p* Delta, slopes dP*/dgbar* in units of p*/Delta.
module wa_cli_units
   use wa_kinds, only: wp
   implicit none
   private

   public :: si_scales_type, si_column

   !> The scales of one SI input (given = .false.: dimensionless input).
   type :: si_scales_type
      logical :: given = .false.
      !> E* [Pa], p* = pi E* Delta/L [Pa], p* L [N/m], L [m], Delta [m], p* Delta [J/m^2]
      real(wp) :: estar = 0.0_wp, pressure = 0.0_wp, force = 0.0_wp, length = 0.0_wp, &
         delta = 0.0_wp, energy = 0.0_wp
   end type si_scales_type

contains

   !> The SI column made from the dimensionless column `name`: its name (e.g. a_star ->
   !> a_m, P_star -> P_Pa, gbar -> gbar_m), unit and factor; si_name = "" when the column
   !> has no unit (alpha, mu, codes, flags).
   pure subroutine si_column(name, scales, si_name, unit, factor)
      character(len=*), intent(in) :: name
      type(si_scales_type), intent(in) :: scales
      character(len=:), allocatable, intent(out) :: si_name, unit
      real(wp), intent(out) :: factor
      character(len=:), allocatable :: base, suffix
      base = name
      if (len(base) > 5) then
         if (base(len(base) - 4:) == "_star") base = base(:len(base) - 5)
      end if
      si_name = ""
      unit = ""
      factor = 1.0_wp
      if (name == "x_star" .or. name == "b_star" .or. starts(name, "a_") .or. &
         starts(name, "c_")) then
         unit = "m"; suffix = "_m"; factor = scales%length
      else if (starts(name, "P_") .or. name == "traction") then
         unit = "Pa"; suffix = "_Pa"; factor = scales%pressure
      else if (name == "gbar" .or. name == "gap" .or. starts(name, "g_")) then
         unit = "m"; suffix = "_m"; factor = scales%delta
      else if (starts(name, "dPdg_")) then
         unit = "Pa/m"; suffix = "_Pa_per_m"; factor = scales%pressure/scales%delta
      else if (starts(name, "W_star") .or. starts(name, "jump_energ")) then
         unit = "J/m^2"; suffix = "_J_per_m2"; factor = scales%energy
      else
         return
      end if
      si_name = base//suffix
   end subroutine si_column

   pure logical function starts(text, head)
      character(len=*), intent(in) :: text, head
      starts = .false.
      if (len(text) >= len(head)) starts = text(1:len(head)) == head
   end function starts

end module wa_cli_units
