!> Measures the supported range of every entry point (doc/theory.md, "Supported range"):
!>   cd study && fpm run --profile release wavyadhesion-range
!> 1. Point solvers (dw/md_equilibrium, dw/md_roots) over the whole accepted domain
!>    (alpha 1e-12 .. 1e12, mu 0 and 1e-100 .. 1e100, a* from 0 to 1/2): status counts per
!>    a* band, every wa_ok state checked for consistency (finite, a* <= c* <= 1/2, zone case),
!>    and the largest deviation from the JKR limit where mu >= 1e12.
!> 2. Tracer (critical_forces, which traces the branch and walks the load path): per alpha,
!>    the mu (0.5-decade grid) where it first fails and the largest mu where it succeeds.
program supported_range
   use wavyadhesion
   use wa_kinds, only: wp
   implicit none
   integer, parameter :: n_a = 15
   real(wp), parameter :: a_list(n_a) = [0.0_wp, 1.0e-300_wp, 1.0e-200_wp, 1.0e-150_wp, &
      1.0e-120_wp, 1.0e-100_wp, 1.0e-50_wp, 1.0e-12_wp, 1.0e-6_wp, 0.1_wp, 0.25_wp, 0.4_wp, &
      0.5_wp - 1.0e-9_wp, 0.5_wp - 1.0e-15_wp, 0.5_wp]
   character(len=*), parameter :: band_name(5) = [character(len=24) :: "a* = 0", &
      "0 < a* < 1e-150", "1e-150 <= a* < 1e-100", "1e-100 <= a* < 1e-12", "1e-12 <= a* <= 1/2"]
   integer :: model
   do model = model_dw, model_md
      call point_solvers(model)
   end do
   do model = model_dw, model_md
      call tracer(model)
   end do

contains

   integer function band(a)
      real(wp), intent(in) :: a
      if (a == 0.0_wp) then
         band = 1
      else if (a < 1.0e-150_wp) then
         band = 2
      else if (a < 1.0e-100_wp) then
         band = 3
      else if (a < 1.0e-12_wp) then
         band = 4
      else
         band = 5
      end if
   end function band

   subroutine point_solvers(model)
      integer, intent(in) :: model
      type(params_type) :: p
      type(state_type) :: s, states(64)
      integer :: counts(5, 0:5), bad, ia, im, k, st, n, i
      real(wp) :: alpha, mu, dev_jkr, dev
      counts = 0; bad = 0; dev_jkr = 0.0_wp
      do ia = -12, 12
         alpha = min(alpha_max, max(alpha_min, 10.0_wp**ia))
         do im = -21, 20
            mu = 0.0_wp
            if (im > -21) mu = min(mu_max, max(mu_min, 10.0_wp**(5*im)))
            call new_params(alpha, mu, p, st)
            if (st /= wa_ok) error stop "domain point refused"
            do k = 1, n_a
               call model_equilibrium(model, p, a_list(k), s, st)
               counts(band(a_list(k)), st) = counts(band(a_list(k)), st) + 1
               if (st == wa_ok) then
                  if (.not. consistent(s)) bad = bad + 1
                  if (mu >= 1.0e12_wp .and. a_list(k) >= 1.0e-6_wp .and. &
                     a_list(k) <= 0.5_wp - 1.0e-9_wp .and. s%zone_case == zone_inside) then
                     dev = abs(s%p_star - jkr_load(alpha, a_list(k)))/max(1.0_wp, &
                        abs(jkr_load(alpha, a_list(k))))
                     dev_jkr = max(dev_jkr, dev)
                  end if
               end if
               call model_roots(model, p, a_list(k), states, n, st)
               if (st == wa_ok) then
                  do i = 1, n
                     if (.not. consistent(states(i))) bad = bad + 1
                  end do
               end if
            end do
         end do
      end do
      print '(a)', ""
      print '(a,a,a)', "## ", trim(model_label(model)), ": point solvers over the accepted domain"
      print '(a)', "| a* band | states | ok | no solution | not converged | numerical error |"
      print '(a)', "|---|---|---|---|---|---|"
      do k = 1, 5
         print '("| ",a," | ",i0," | ",i0," | ",i0," | ",i0," | ",i0," |")', &
            trim(band_name(k)), sum(counts(k, :)), counts(k, 0), counts(k, 2), counts(k, 3), &
            counts(k, 5)
      end do
      print '(a,i0)', "inconsistent wa_ok states (equilibrium and roots): ", bad
      print '(a,es9.2)', "largest |P* - P*_JKR|/max(1,|P*_JKR|), mu >= 1e12, case 1: ", dev_jkr
   end subroutine point_solvers

   logical function consistent(s)
      type(state_type), intent(in) :: s
      consistent = abs(s%p_star) <= huge(1.0_wp) .and. s%c_star >= s%a_star .and. &
         s%c_star <= 0.5_wp .and. s%a_star >= 0.0_wp
      select case (s%zone_case)
      case (zone_inside)
         consistent = consistent .and. s%c_star < 0.5_wp
      case (zone_whole_period)
         consistent = consistent .and. s%c_star == 0.5_wp
      case (zone_full_contact)
         consistent = consistent .and. s%a_star == 0.5_wp
      case default
         consistent = .false.
      end select
   end function consistent

   subroutine tracer(model)
      integer, intent(in) :: model
      type(params_type) :: p
      real(wp) :: fc, pf, mu, mu_first_fail, mu_last_ok
      integer :: ia, j, st, fails, oks, streak, last_status
      print '(a)', ""
      print '(a,a,a)', "## ", trim(model_label(model)), &
         ": critical_forces (trace + load path), mu = 0 and 10^(j/2) from 1e-4 up"
      print '(a)', "| alpha | ok | failed | first failing mu | largest mu ok | status there |"
      print '(a)', "|---|---|---|---|---|---|"
      do ia = -12, 12, 2
         call new_params(min(alpha_max, max(alpha_min, 10.0_wp**ia)), 0.0_wp, p, st)
         call critical_forces(model, p, fc, pf, st)
         fails = merge(0, 1, st == wa_ok); oks = 1 - fails
         mu_first_fail = huge(1.0_wp); mu_last_ok = 0.0_wp; streak = 0; last_status = 0
         do j = -8, 200
            mu = min(mu_max, 10.0_wp**(0.5_wp*j))
            call new_params(min(alpha_max, max(alpha_min, 10.0_wp**ia)), mu, p, st)
            call critical_forces(model, p, fc, pf, st)
            if (st == wa_ok .and. abs(fc) <= huge(fc) .and. .not. isnan(pf)) then
               oks = oks + 1; mu_last_ok = mu; streak = 0
            else
               fails = fails + 1; streak = streak + 1; last_status = st
               mu_first_fail = min(mu_first_fail, mu)
               if (streak >= 6) exit
            end if
         end do
         print '("| 1e",i0," | ",i0," | ",i0," | ",es8.1," | ",es8.1," | ",i0," |")', ia, oks, &
            fails, merge(mu_first_fail, -1.0_wp, fails > 0), mu_last_ok, last_status
      end do
   end subroutine tracer

   character(len=8) function model_label(model)
      integer, intent(in) :: model
      model_label = merge("DW", "MD", model == model_dw)
   end function model_label

end program supported_range
