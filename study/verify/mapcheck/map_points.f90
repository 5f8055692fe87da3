!> Every boundary point of an adhesion map (both controls) on an alpha grid, rebisected
!> independently from a bracket of +-1e-7 around it (mechanism_change for load control,
!> gap_mechanism_change for gap control, to 1e-10): the worst relative difference in mu
!> per control and every point that differs by more than 1e-8 or whose bracket holds no
!> single change. The unit test `map` does this for DW at 20 alpha and MD at 2 (it must
!> stay fast); this does MD (or DW) at 20.
!>   cd study && fpm run --profile release wavyadhesion-mapcheck [-- dw|md [N_ALPHA]]
program map_points
   use wavyadhesion
   use wa_kinds, only: wp
   implicit none
   type(map_type) :: map
   real(wp), allocatable :: alpha(:)
   real(wp) :: mu_c, worst(2), d, c0, c1
   integer :: status, c, p, j, n(2), n_off, k, model, n_alpha
   character(len=16) :: arg

   model = model_md
   n_alpha = 20
   if (command_argument_count() >= 1) then
      call get_command_argument(1, arg)
      if (arg == "dw") model = model_dw
   end if
   if (command_argument_count() >= 2) then
      call get_command_argument(2, arg)
      read (arg, *) n_alpha
   end if
   alpha = [(10.0_wp**(-2.0_wp + 3.0_wp*real(j - 1, wp)/real(n_alpha - 1, wp)), &
      j = 1, n_alpha)]
   call cpu_time(c0)
   call adhesion_map(model, alpha, 1.0e-3_wp, 1.0e3_wp, 60, map, status, &
      scan_every=max(1, n_alpha/4), control=map_control_both)
   call cpu_time(c1)
   write (*, '(a,a,i0,a,i0,a,f6.2,a)') merge("DW", "MD", model == model_dw), " map of ", &
      n_alpha, " alpha (0.01..10), both controls: ", map%n_boundaries, " curves, ", c1 - c0, " s"
   if (status /= 0) write (*, '(a,i0)') "map status ", status
   worst = 0.0_wp
   n = 0
   n_off = 0
   do c = 1, map%n_boundaries
      associate (b => map%boundary(c))
         do p = 1, b%n
            if (.not. any(alpha == b%alpha(p))) cycle
            k = merge(1, 2, b%which <= 2)
            if (b%which <= 2) then
               call mechanism_change(model, b%alpha(p), b%which, b%mu(p)*(1.0_wp - 1.0e-7_wp), &
                  b%mu(p)*(1.0_wp + 1.0e-7_wp), mu_c, status)
            else
               call gap_mechanism_change(model, b%alpha(p), b%which, &
                  b%mu(p)*(1.0_wp - 1.0e-7_wp), b%mu(p)*(1.0_wp + 1.0e-7_wp), mu_c, status)
            end if
            n(k) = n(k) + 1
            d = abs(mu_c - b%mu(p))/b%mu(p)
            if (status == 0) worst(k) = max(worst(k), d)
            if (status /= 0 .or. d > 1.0e-8_wp) then
               n_off = n_off + 1
               write (*, '(a,i0,a,es22.14,a,es22.14,a,i0,a,es9.2)') "  differs: code ", &
                  b%code, " alpha ", b%alpha(p), " mu ", b%mu(p), " status ", status, &
                  " relative ", d
            end if
         end do
      end associate
   end do
   write (*, '(a,i0,a,es9.2,a,i0,a,es9.2,a,i0)') "load control: ", n(1), &
      " points, worst ", worst(1), "; gap control: ", n(2), " points, worst ", worst(2), &
      "; points beyond 1e-8 or without a single change in +-1e-7: ", n_off
end program map_points
