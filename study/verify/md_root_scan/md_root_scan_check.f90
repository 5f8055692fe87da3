!> Brute-force check of the root bracketing of md_roots: on a dense grid of (alpha, mu, a*)
!> count the sign changes of md_opening - Dcod on a fine grid in c*-a* (logistic in
!> ln, step 0.004, from 1e-26 to 1 - 1e-26 of 1/2 - a*) plus the case-2 state, and
!> compare with the number of states md_roots returns. (Within ~1e-16 (1/2 - a*) of
!> c* = 1/2 the fine grid cannot resolve 1/2 - c*; there md_roots is the finer tool.)
!> Run by study/md_study.sh scan (about 30 min); prints the mismatches and a histogram
!> of case-1 roots (last run: 32000 points, 0 mismatches, 9641/18143/4216/0).
program md_root_scan_check
   use wa_kinds, only: wp
   use wa_params, only: params_type, new_params
   use wa_state, only: state_type
   use wa_md, only: md_roots, md_opening, md_midgap_opening
   implicit none
   real(wp), parameter :: alphas(*) = [0.01_wp, 0.05_wp, 0.1_wp, 0.3_wp, 0.6_wp, 1.0_wp, &
      2.0_wp, 10.0_wp]
   real(wp), parameter :: mus(*) = [0.01_wp, 0.5_wp, 1.0_wp, 2.0_wp, 2.5_wp, 3.0_wp, 5.0_wp, &
      10.0_wp, 30.0_wp, 1000.0_wp]
   integer, parameter :: n_a = 400
   type(params_type) :: p
   type(state_type) :: states(8)
   integer :: ia, im, k, status, n, n_fine, n_case2, n_mismatch, histogram(0:3), n_points
   real(wp) :: a

   n_mismatch = 0; histogram = 0; n_points = 0
   do ia = 1, size(alphas)
      do im = 1, size(mus)
         call new_params(alphas(ia), mus(im), p, status)
         do k = 1, n_a
            a = 0.5_wp*real(k, wp)/real(n_a + 1, wp)
            call md_roots(p, a, states, n, status)
            n_fine = fine_count(p, a)
            n_case2 = merge(1, 0, md_midgap_opening(a) <= p%dcod)
            histogram(min(n_fine, 3)) = histogram(min(n_fine, 3)) + 1
            n_points = n_points + 1
            if (status /= 0 .or. n /= n_fine + n_case2) then
               n_mismatch = n_mismatch + 1
               print '(a,3es12.4,a,i0,a,i0,a,i0)', "mismatch alpha mu a*", alphas(ia), &
                  mus(im), a, ": status ", status, ", states ", n, ", fine scan ", n_fine
            end if
         end do
      end do
   end do
   print '(i0,a,i0,a,4(i0,1x))', n_points, " points, mismatches ", n_mismatch, &
      "; points with 0/1/2/3+ case-1 roots: ", histogram

contains

   integer function fine_count(p, a) result(n_changes)
      type(params_type), intent(in) :: p
      real(wp), intent(in) :: a
      real(wp) :: u, f, f_prev, width
      width = 0.5_wp - a
      n_changes = 0
      u = -60.0_wp
      f_prev = md_opening(p, a, width/(1.0_wp + exp(-u))) - p%dcod
      do while (u < 60.0_wp)
         u = u + 0.004_wp
         f = md_opening(p, a, width/(1.0_wp + exp(-u))) - p%dcod
         if ((f < 0.0_wp) .neqv. (f_prev < 0.0_wp)) n_changes = n_changes + 1
         f_prev = f
      end do
      ! beyond the grid up to c* = 1/2
      if ((f_prev < 0.0_wp) .neqv. (md_midgap_opening(a) - p%dcod < 0.0_wp)) &
         n_changes = n_changes + 1
   end function fine_count

end program md_root_scan_check
