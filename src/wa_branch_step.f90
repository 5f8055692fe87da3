!> display: none
!>
!> One step of the pseudo-arclength continuation on the case-1 curve F(a*, y) = 0 (wa_curve)
!> in the scaled plane z = (a*, w y), and the location of the events within a step. A point
!> carries its unit tangent, dP*/dsigma and the stability determinant; the corrector is
!> Newton on F(z) = 0, t . (z - z_pred) = 0 from the tangent predictor. Located within a
!> step: the zero of dP*/dsigma (a fold) or of da*/dsigma (a* turns back), where the curve
!> reaches y_max (the switch to case 2, c* = 1/2), and the extremum of P* before a switch;
!> case-2 points (explicit in a*) and the extremum at a corner.
module wa_branch_step
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use wa_kinds, only: wp, pi
   use wa_status, only: wa_ok, wa_not_converged, wa_numerical_error, set_error
   use wa_params, only: params_type
   use wa_state, only: state_type, zone_inside, zone_whole_period
   use wa_curve, only: curve_residual, curve_values, curve_y_max, curve_weight, &
      curve_equilibrium
   use wa_roots, only: brent_type, brent_init, brent_propose, brent_accept, golden_type, &
      golden_init, golden_propose, golden_accept
   implicit none
   private

   public :: curve_point, corrector, orient, locate_zero, crosses_case2, case1_extremum, &
      switch_abscissa, case2_point, case2_slope, corner_extremum

   !> A point of the curve in the scaled plane, with its derivatives.
   type :: curve_point
      real(wp) :: a = 0.0_wp, y = 0.0_wp
      integer :: zone_case = zone_inside
      !> unit tangent (da, w dy) in the direction of travel
      real(wp) :: t(2) = 0.0_wp
      !> dP*/dsigma along the direction of travel
      real(wp) :: dp = 0.0_wp
      !> D = P_a F_y - P_y F_a (case 1): > 0 where the state is stable under load control
      real(wp) :: det = 0.0_wp
   end type curve_point

   integer, parameter :: max_newton = 12
   !> |F| at which the corrector's point is on the curve to rounding (F is a logarithm of
   !> O(1) ratios: its own rounding is a few epsilon)
   real(wp), parameter :: f_floor = 4.0_wp*epsilon(1.0_wp)

contains

   !> Predictor z + h t, then Newton on F = 0, t.(z - z_pred) = 0.
   pure subroutine corrector(model, params, p, h, q, iters, ok)
      integer, intent(in) :: model
      type(params_type), intent(in) :: params
      type(curve_point), intent(in) :: p
      real(wp), intent(in) :: h
      type(curve_point), intent(out) :: q
      integer, intent(out) :: iters
      logical, intent(out) :: ok
      real(wp) :: w, z(2), zp(2), g(2), f, r2, det, dz(2)

      w = curve_weight(model)
      zp = [p%a, w*p%y] + h*p%t
      z = zp
      ok = .false.
      do iters = 1, max_newton
         if (z(1) <= 0.0_wp .or. z(1) >= 0.5_wp .or. z(2)/w > curve_y_max) return
         call residual_gradient(model, params, z(1), z(2)/w, f, g)
         g(2) = g(2)/w
         if (.not. (ieee_is_finite(f) .and. all(ieee_is_finite(g)))) return
         r2 = dot_product(p%t, z - zp)
         det = g(1)*p%t(2) - g(2)*p%t(1)
         if (det == 0.0_wp) return
         dz = [(-f*p%t(2) + r2*g(2))/det, (-g(1)*r2 + p%t(1)*f)/det]
         z = z + dz
         ! converged; or F at its rounding floor where the gradient is small (MD near a
         ! reconnection of the case-1 curve: |grad F| ~ 1e-2), which keeps the steps at
         ! ~1e-14 however small h is
         if (norm2(dz) <= 1.0e-14_wp*max(1.0_wp, norm2(z)) .or. (abs(f) <= f_floor .and. &
            norm2(dz) <= 1.0e-12_wp*max(1.0_wp, norm2(z)))) then
            ok = .true.
            exit
         end if
      end do
      if (ok) call polish(model, params, z(1), z(2), w, g(2)*w)
      q%a = z(1)
      q%y = z(2)/w
      q%zone_case = zone_inside
   end subroutine corrector

   !> Newton steps in y at fixed a*: the corrector's step test acts on w y, which
   !> leaves y (and a steep P*(y) near a* -> 1/2) short of full precision.
   pure subroutine polish(model, params, a, wy, w, f_y)
      integer, intent(in) :: model
      type(params_type), intent(in) :: params
      real(wp), intent(in) :: a, w, f_y
      real(wp), intent(inout) :: wy
      real(wp) :: f, dy, slope, h
      integer :: k
      slope = f_y
      do k = 1, 3
         f = curve_residual(model, params, a, wy/w)
         if (.not. ieee_is_finite(f) .or. slope == 0.0_wp) return
         if (k == 1) then                  ! a local slope: F may be steep on a small scale
            h = -1.0e-9_wp*max(1.0_wp, abs(wy/w))
            slope = (curve_residual(model, params, a, wy/w + h) - f)/h
            if (slope == 0.0_wp .or. .not. ieee_is_finite(slope)) slope = f_y
         end if
         dy = -f/slope
         if (abs(dy) > 1.0e-6_wp*max(1.0_wp, abs(wy/w)) .or. &
            wy/w + dy > curve_y_max) return
         wy = wy + w*dy
      end do
   end subroutine polish

   !> F and its forward-difference gradient (enough for Newton's direction).
   pure subroutine residual_gradient(model, params, a, y, f, g)
      integer, intent(in) :: model
      type(params_type), intent(in) :: params
      real(wp), intent(in) :: a, y
      real(wp), intent(out) :: f, g(2)
      real(wp) :: ha, hy
      f = curve_residual(model, params, a, y)
      ! F varies on the scale of the distance to the nearer end of 0 < a* < 1/2
      ha = 1.0e-7_wp*min(max(a, 1.0e-3_wp), 0.5_wp - a)
      if (a + ha >= 0.5_wp) ha = -ha
      hy = -1.0e-7_wp*max(abs(y), 1.0_wp)
      g(1) = (curve_residual(model, params, a + ha, y) - f)/ha
      g(2) = (curve_residual(model, params, a, y + hy) - f)/hy
   end subroutine residual_gradient

   !> Unit tangent of the case-1 curve at q, oriented along `previous`, and dP*/dsigma.
   pure subroutine orient(model, params, q, previous)
      integer, intent(in) :: model
      type(params_type), intent(in) :: params
      type(curve_point), intent(inout) :: q
      real(wp), intent(in) :: previous(2)
      real(wp) :: fa, fy, pa, py, w
      w = curve_weight(model)
      call accurate_partials(model, params, q%a, q%y, fa, fy, pa, py)
      q%t = [fy/w, -fa]
      q%t = q%t/norm2(q%t)
      if (dot_product(q%t, previous) < 0.0_wp) q%t = -q%t
      q%dp = pa*q%t(1) + py*(q%t(2)/w)
      q%det = pa*fy - py*fa
   end subroutine orient

   !> Five-point differences of F and P* in a* and y (one-sided where the domain ends):
   !> error ~ h^4, accurate to ~1e-12, which places folds to ~1e-11 in a*.
   pure subroutine accurate_partials(model, params, a, y, fa, fy, pa, py)
      integer, intent(in) :: model
      type(params_type), intent(in) :: params
      real(wp), intent(in) :: a, y
      real(wp), intent(out) :: fa, fy, pa, py
      real(wp) :: ha, hy, fv(0:4), pv(0:4)
      integer :: k

      ha = 2.0e-3_wp*min(a, 0.5_wp - a, 0.05_wp)
      do k = 0, 4
         call values_at(a + (k - 2)*ha, y, fv(k), pv(k))
      end do
      fa = central5(fv, ha)
      pa = central5(pv, ha)
      ! in y the functions vary on the scale of the distance to y_max (c* = 1/2): a
      ! central stencil well inside it (its centre is the a* stencil's), a one-sided one
      ! below y_max on the boundary
      hy = min(2.0e-3_wp*max(1.0_wp, abs(y)), 0.02_wp*(curve_y_max - y))
      if (hy > 0.0_wp) then
         do k = 0, 4
            if (k /= 2) call values_at(a, y + (k - 2)*hy, fv(k), pv(k))
         end do
         fy = central5(fv, hy)
         py = central5(pv, hy)
      else
         hy = 2.0e-3_wp
         do k = 0, 4
            call values_at(a, y - k*hy, fv(k), pv(k))
         end do
         fy = -onesided5(fv, hy)
         py = -onesided5(pv, hy)
      end if
   contains
      pure subroutine values_at(aa, yy, fval, pval)
         real(wp), intent(in) :: aa, yy
         real(wp), intent(out) :: fval, pval
         call curve_values(model, params, aa, yy, fval, pval)
      end subroutine values_at
   end subroutine accurate_partials

   pure real(wp) function central5(v, h)
      real(wp), intent(in) :: v(0:4), h
      central5 = (v(0) - 8.0_wp*v(1) + 8.0_wp*v(3) - v(4))/(12.0_wp*h)
   end function central5

   pure real(wp) function onesided5(v, h)
      real(wp), intent(in) :: v(0:4), h
      onesided5 = (-25.0_wp*v(0) + 48.0_wp*v(1) - 36.0_wp*v(2) + 16.0_wp*v(3) - 3.0_wp*v(4)) &
         /(12.0_wp*h)
   end function onesided5

   !> Brent over the arclength between p and the accepted step h for the zero of
   !> dP*/dsigma (which = 1, a fold) or of da*/dsigma (which = 2, a* turns back).
   subroutine locate_zero(model, params, p, h, which, f, status, errmsg)
      integer, intent(in) :: model, which
      type(params_type), intent(in) :: params
      type(curve_point), intent(in) :: p
      real(wp), intent(in) :: h
      type(curve_point), intent(out) :: f
      integer, intent(out) :: status
      character(len=*), intent(inout), optional :: errmsg
      type(brent_type) :: solver
      real(wp) :: sigma
      logical :: done, ok
      integer :: iter, iters

      status = wa_ok
      call corrector(model, params, p, h, f, iters, ok)
      call orient(model, params, f, p%t)
      call brent_init(solver, 0.0_wp, monitored(p), h, monitored(f), 1.0e-13_wp)
      do iter = 1, 100
         call brent_propose(solver, sigma, done)
         if (done) exit
         call corrector(model, params, p, sigma, f, iters, ok)
         if (.not. ok) exit
         call orient(model, params, f, p%t)
         call brent_accept(solver, monitored(f))
      end do
      call corrector(model, params, p, solver%b, f, iters, ok)
      if (.not. (done .and. ok)) then
         call set_error(wa_not_converged, "trace_branch: a fold could not be located", &
            status, errmsg)
         return
      end if
      call orient(model, params, f, p%t)
   contains
      pure real(wp) function monitored(q)
         type(curve_point), intent(in) :: q
         monitored = merge(q%dp, q%t(1), which == 1)
      end function monitored
   end subroutine locate_zero

   !> Does the curve leave case 1 (reach y_max) within the next step?
   logical function crosses_case2(model, params, p, h)
      integer, intent(in) :: model
      type(params_type), intent(in) :: params
      type(curve_point), intent(in) :: p
      real(wp), intent(in) :: h
      real(wp) :: a_next
      a_next = min(0.5_wp - 1.0e-15_wp, max(1.0e-300_wp, p%a + 2.0_wp*h*p%t(1)))
      ! F(a*, y_max) changes sign across the a* where the curve reaches y_max; but it also
      ! changes where another sheet is born at y_max (MD: a second case-1 root and case 2
      ! appear together), so the curve itself must be heading into y_max within the step
      crosses_case2 = p%t(2) > 0.0_wp .and. &
         curve_weight(model)*(curve_y_max - p%y) <= h*p%t(2)
      if (crosses_case2) crosses_case2 = &
         curve_residual(model, params, a_next, curve_y_max) &
         *curve_residual(model, params, p%a, curve_y_max) <= 0.0_wp
   end function crosses_case2

   !> The extremum of P* (a maximum for sgn = +1) on the case-1 curve between a* = a1 and
   !> a2: golden sections on P*(a*) of the state nearest c_hint, to 1e-12 relative in a*.
   subroutine case1_extremum(model, params, c_hint, a1, a2, sgn, s, status, errmsg)
      integer, intent(in) :: model
      type(params_type), intent(in) :: params
      real(wp), intent(in) :: c_hint, a1, a2, sgn
      type(state_type), intent(out) :: s
      integer, intent(out) :: status
      character(len=*), intent(inout), optional :: errmsg
      type(golden_type) :: gs
      real(wp) :: x
      integer :: iter, slot
      logical :: done, moved
      status = wa_ok
      ! the maximum of sgn P*: the minimum of -sgn P*, equal values keeping the right part
      call golden_init(gs, min(a1, a2), max(a1, a2), 0.0_wp, 1.0e-12_wp, ties_left=.false.)
      do iter = 1, 202                        ! the two first points and 200 sections
         call golden_propose(gs, x, done, slot, moved)
         if (done) exit
         call golden_accept(gs, -sgn*load_at(x))
         if (status /= wa_ok .and. iter > 1) exit
      end do
      if (status /= wa_ok) return
      call curve_equilibrium(model, params, 0.5_wp*(gs%lo + gs%hi), c_hint, s, status, errmsg)
      if (status /= wa_ok) return
      if (s%zone_case /= zone_inside) call set_error(wa_numerical_error, "trace_branch: "// &
         "a fold before a case switch could not be located", status, errmsg)
   contains
      real(wp) function load_at(a)
         real(wp), intent(in) :: a
         type(state_type) :: st
         call curve_equilibrium(model, params, a, c_hint, st, status, errmsg)
         load_at = st%p_star
      end function load_at
   end subroutine case1_extremum

   !> The a* where F(a*, y_max) = 0 between a1 and a2 (case switch, to ~1e-15).
   function switch_abscissa(model, params, a1, v1, a2, v2, status, errmsg) result(a)
      integer, intent(in) :: model
      type(params_type), intent(in) :: params
      real(wp), intent(in) :: a1, v1, a2, v2
      integer, intent(out) :: status
      character(len=*), intent(inout), optional :: errmsg
      real(wp) :: a
      type(brent_type) :: solver
      logical :: done
      integer :: iter
      status = wa_ok
      if (v1*v2 > 0.0_wp) then
         a = a1
         call set_error(wa_numerical_error, "trace_branch: case switch not bracketed", &
            status, errmsg)
         return
      end if
      call brent_init(solver, a1, v1, a2, v2, 1.0e-16_wp)
      do iter = 1, 200
         call brent_propose(solver, a, done)
         if (done) exit
         call brent_accept(solver, curve_residual(model, params, a, curve_y_max))
      end do
      a = solver%b
   end function switch_abscissa

   !> A case-2 point at a*, travelling in direction dir of a*; P* = A^2 - const.
   pure function case2_point(model, a, dir) result(q)
      integer, intent(in) :: model
      real(wp), intent(in) :: a, dir
      type(curve_point) :: q
      q%a = a
      q%y = curve_y_max
      q%zone_case = zone_whole_period
      q%t = [dir, 0.0_wp]
      q%dp = dir*case2_slope(a)
   end function case2_point

   !> dP*/da* in case 2: d(A^2)/da* = pi sin(2 pi a*)   (2.28a)
   pure real(wp) function case2_slope(a)
      real(wp), intent(in) :: a
      case2_slope = pi*sin(2.0_wp*pi*a)
   end function case2_slope

   !> Extremum at a corner: +1 if P* rose into it and falls after, -1 the reverse.
   pure integer function corner_extremum(before, after)
      real(wp), intent(in) :: before, after
      corner_extremum = 0
      if (before > 0.0_wp .and. after < 0.0_wp) corner_extremum = 1
      if (before < 0.0_wp .and. after > 0.0_wp) corner_extremum = -1
   end function corner_extremum

end module wa_branch_step
