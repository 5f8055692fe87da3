!> Traction-gap laws of the smooth-adhesion (boundary-element) model, in the library's
!> units: gaps over Delta, tractions over p* (tension positive), work of adhesion over
!> p* Delta. A law is one kind code and its two scales; a second law costs one more case
!> in law_eval (value and slope) and law_potential (doc/theory.md, "Smooth adhesion").
module wa_bem_law
   use wa_kinds, only: wp, pi
   implicit none
   private

   public :: bem_law_type, lj_law, law_eval, law_curvature, law_potential, law_zero, law_peak
   public :: law_lj39

   !> The Lennard-Jones 3-9 law sigma(h) = (8 dgamma/(3 eps)) ((eps/h)^3 - (eps/h)^9)
   integer, parameter :: law_lj39 = 1

   !> A traction-gap law: kind and its scales.
   type :: bem_law_type
      integer :: kind = law_lj39
      !> Work of adhesion over p* Delta (the integral of the tension beyond the zero)
      real(wp) :: dgamma = 0.0_wp
      !> Range over Delta: the gap at which the traction vanishes (LJ: eps)
      real(wp) :: eps = 1.0_wp
   end type bem_law_type

contains

   !> The LJ 3-9 law of (alpha, mu) with the work of adhesion and range of the cohesive
   !> models: dgamma = pi alpha^2/2, eps = 2 Dcod = (4 alpha^4)^(1/3)/mu (mu > 0).
   pure function lj_law(alpha, mu) result(law)
      !> Johnson's parameter alpha > 0 (params_type%alpha); not checked here (new_params
      !> checks it)
      real(wp), intent(in) :: alpha
      !> Transition parameter mu > 0 (params_type%mu); not checked here: mu = 0 has no LJ
      !> law (its range eps would be infinite)
      real(wp), intent(in) :: mu
      type(bem_law_type) :: law
      law%kind = law_lj39
      law%dgamma = 0.5_wp*pi*alpha**2
      law%eps = (4.0_wp*alpha**4)**(1.0_wp/3.0_wp)/mu
   end function lj_law

   !> Traction sigma(h) (tension positive) and its slope d sigma/dh, for h > 0.
   elemental subroutine law_eval(law, h, sigma, slope)
      type(bem_law_type), intent(in) :: law
      real(wp), intent(in) :: h
      real(wp), intent(out) :: sigma, slope
      real(wp) :: s3, s9, c
      select case (law%kind)
      case default   ! law_lj39
         s3 = (law%eps/h)**3
         s9 = s3**3
         c = 8.0_wp*law%dgamma/(3.0_wp*law%eps)
         sigma = c*(s3 - s9)
         slope = c*(9.0_wp*s9 - 3.0_wp*s3)/h
      end select
   end subroutine law_eval

   !> Second derivative d^2 sigma/dh^2, for h > 0 (the sign of an eigenvalue's crossing
   !> at a fold).
   elemental function law_curvature(law, h) result(c2)
      type(bem_law_type), intent(in) :: law
      real(wp), intent(in) :: h
      real(wp) :: c2, s3
      select case (law%kind)
      case default   ! law_lj39
         s3 = (law%eps/h)**3
         c2 = 8.0_wp*law%dgamma/(3.0_wp*law%eps)*(12.0_wp*s3 - 90.0_wp*s3**3)/h**2
      end select
   end function law_curvature

   !> Interaction energy per area phi(h) = -integral_h^inf sigma, so d phi/dh = sigma and
   !> phi(zero of the law) = -dgamma.
   elemental function law_potential(law, h) result(phi)
      type(bem_law_type), intent(in) :: law
      real(wp), intent(in) :: h
      real(wp) :: phi, s2
      select case (law%kind)
      case default
         s2 = (law%eps/h)**2
         phi = -law%dgamma*(4.0_wp*s2 - s2**4)/3.0_wp
      end select
   end function law_potential

   !> The gap at which the traction changes sign (the edge of the repulsive part).
   pure function law_zero(law) result(h)
      type(bem_law_type), intent(in) :: law
      real(wp) :: h
      h = law%eps
   end function law_zero

   !> The gap of the peak tension (LJ: 3^(1/6) eps, peak 16 dgamma/(9 sqrt(3) eps)).
   pure function law_peak(law) result(h)
      type(bem_law_type), intent(in) :: law
      real(wp) :: h
      h = 3.0_wp**(1.0_wp/6.0_wp)*law%eps
   end function law_peak

end module wa_bem_law
