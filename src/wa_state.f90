!> An equilibrium state of a cohesive-zone model at a given contact half-width.
module wa_state
   use wa_kinds, only: wp
   implicit none
   private

   !> Zone cases (doc/theory.md, "Double-Westergaard"): 1 a* < c* < 1/2, 2 a* < c* = 1/2, 3 full contact;
   !> 0 no contact (MD only: a* = 0, a Dugdale zone |x*| < c* around the crest).
   integer, parameter, public :: zone_inside = 1, zone_whole_period = 2, zone_full_contact = 3
   integer, parameter, public :: zone_no_contact = 0

   !> Model codes (values shared with the C header, include/wavyadhesion.h).
   integer, parameter, public :: model_westergaard = 0, model_jkr = 1, model_dw = 2, model_md = 3

   type, public :: state_type
      !> Contact half-width over the period, a*
      real(wp) :: a_star = 0.0_wp
      !> Interaction-zone half-width over the period, c* (1/2 in case 2)
      real(wp) :: c_star = 0.0_wp
      !> c* - a*, kept separately: accurate where the zone collapses (large mu)
      real(wp) :: gap_width = 0.0_wp
      !> Load per period over p* L (negative = tensile)
      real(wp) :: p_star = 0.0_wp
      !> 1, 2 or 3 (zone_inside, zone_whole_period, zone_full_contact); 0 zone_no_contact
      integer :: zone_case = 0
      !> Mean gap over one period over Delta, gbar* (wa_separation); -1 where not computed
      real(wp) :: gbar = -1.0_wp
   end type state_type

end module wa_state
