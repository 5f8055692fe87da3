!> The wavyadhesion library: adhesive contact of a wavy elastic surface against a flat.
!> The umbrella module: `use wavyadhesion` gives the whole public API. Every name it
!> exports starts with a prefix of the library (wa_, model_, zone_, event_, ...) or names
!> a documented routine or type, so a host program can `use wavyadhesion` without `only:`
!> beside its own `wp`, `pi` or `status`; the real kind is `wa_wp`.
module wavyadhesion
   use wa_kinds, only: wa_wp => wp
   use wa_release, only: wa_version
   use wa_status, only: wa_ok, wa_invalid_argument, wa_no_solution, wa_not_converged, &
      wa_capacity_too_small, wa_numerical_error, status_message
   use wa_params, only: params_type, scales_type, new_params, dimensional_params, &
      reduced_modulus, alpha_min, alpha_max, mu_min, mu_max
   use wa_state, only: state_type, zone_inside, zone_whole_period, zone_full_contact, &
      zone_no_contact, model_westergaard, model_jkr, model_dw, model_md
   use wa_kernels, only: westergaard_load, jkr_load, westergaard_pressure, &
      westergaard_displacement, westergaard_gap
   use wa_dw, only: dw_equilibrium, dw_roots, dw_traction, dw_gap, dw_options, dw_istar_agm, &
      dw_istar_carlson, dw_istar_tanh_sinh, dw_istar_qag
   use wa_md, only: md_equilibrium, md_roots, md_options, md_prepare_options, md_psi_rules, &
      md_psi_gauss, md_psi_qaws, md_psi_qag, md_psi_qags
   use wa_models, only: check_model, model_equilibrium, model_roots, model_state, &
      model_profile, state_c_tolerance
   use wa_separation, only: westergaard_mean_gap, jkr_mean_gap, dw_state_gbar, &
      md_state_gbar, dw_mean_gap, state_mean_gap, state_profile, state_traction, state_gap, check_state
   use wa_md_nocontact, only: md_no_contact_crest_gap, md_no_contact_state, &
      md_no_contact_closures, md_no_contact_family
   use wa_branch_types, only: branch_type, trace_options
   use wa_branch, only: trace_branch, event_none, event_fold, event_switch, &
      event_jump_start, event_jump_end, event_full_contact_reached, &
      event_full_contact_left, event_pull_off, event_branch_end, event_a_turn
   use wa_loadpath, only: path_from_branch
   use wa_loadpath, only: path_type, load_path, critical_forces, critical_sweep, &
      mechanism_change, stage_loading, stage_unloading, mechanism_gradual, &
      mechanism_jump_case1, mechanism_jump_case2, mechanism_snap
   use wa_map_types, only: map_type, map_boundary, boundary_code, boundary_meaning, &
      map_end_grid, map_end_inside, map_end_mu_range, map_end_failed, map_point, &
      special_meaning, map_point_meet, map_point_turn, map_point_end, map_point_fail
   use wa_map, only: adhesion_map
   use wa_gappath, only: gap_path_type, gap_path, gap_law, gap_stage_approach, gap_stage_retraction, &
      gap_event_touch, gap_event_contact_made, gap_event_contact_lost, &
      gap_event_interaction_lost, load_jump_energies
   use wa_gapcritical, only: gap_critical_type, gap_critical, gap_critical_sweep, &
      gap_critical_values, gap_critical_count, gap_critical_names
   use wa_map_types, only: map_control_load, map_control_gap, map_control_both
   use wa_gapmech, only: gap_mechanisms, gap_mechanism_change, gap_mechanism_name
   use wa_bem_law, only: bem_law_type, lj_law, law_eval, law_potential, law_zero, law_peak
   use wa_bem_solver, only: lj_problem_type, lj_problem, lj_auto_n, lj_zone_length, &
      lj_max_unknowns, lj_max_auto_n
   use wa_bem_path, only: lj_path_type, lj_cycle_type, lj_paths, lj_cycle, lj_rigid_pull_off, &
      lj_profile, lj_stage_loading, &
      lj_stage_unloading, lj_stage_approach, lj_stage_retraction, lj_path_jump_start, &
      lj_path_jump_end, lj_path_full_contact_reached, lj_path_full_contact_left, lj_path_pull_off
   use wa_bem_trace, only: lj_branch_type, lj_trace_options, lj_trace, lj_event_none, &
      lj_event_load_fold, lj_event_gap_fold, lj_event_full_contact, lj_event_contact, lj_event_end
   implicit none
   private

   !> The library's real kind (C double): declare reals as real(wa_wp) to pass them unchanged.
   public :: wa_wp
   public :: load_jump_energies
   public :: gap_path_type, gap_path, gap_law, gap_stage_approach, gap_stage_retraction, &
      gap_event_touch, gap_event_contact_made, gap_event_contact_lost, &
      gap_event_interaction_lost
   public :: wa_ok, wa_invalid_argument, wa_no_solution, wa_not_converged, &
      wa_capacity_too_small, wa_numerical_error, status_message
   public :: params_type, scales_type, new_params, dimensional_params, reduced_modulus
   public :: alpha_min, alpha_max, mu_min, mu_max
   public :: state_type, zone_inside, zone_whole_period, zone_full_contact
   public :: model_westergaard, model_jkr, model_dw, model_md
   public :: westergaard_load, jkr_load, westergaard_pressure, westergaard_displacement, &
      westergaard_gap
   public :: dw_equilibrium, dw_roots, dw_traction, dw_gap
   public :: dw_options, dw_istar_agm, dw_istar_carlson, dw_istar_tanh_sinh, dw_istar_qag
   public :: md_equilibrium, md_roots
   public :: md_options, md_prepare_options, md_psi_rules, md_psi_gauss, md_psi_qaws, &
      md_psi_qag, md_psi_qags
   public :: check_model, model_equilibrium, model_roots, model_state, model_profile, &
      state_c_tolerance
   public :: westergaard_mean_gap, jkr_mean_gap, dw_state_gbar, md_state_gbar, dw_mean_gap, &
      state_mean_gap, state_profile, state_traction, state_gap, check_state, &
      md_no_contact_crest_gap, md_no_contact_state, md_no_contact_closures, &
      md_no_contact_family, zone_no_contact
   public :: branch_type, trace_options, trace_branch, event_none, event_fold, event_switch, &
      event_jump_start, event_jump_end, event_full_contact_reached, event_full_contact_left, &
      event_pull_off, event_branch_end, event_a_turn
   public :: path_from_branch
   public :: path_type, load_path, critical_forces, critical_sweep, mechanism_change, &
      stage_loading, stage_unloading, mechanism_gradual, mechanism_jump_case1, &
      mechanism_jump_case2, mechanism_snap
   public :: map_type, map_boundary, adhesion_map, boundary_code, boundary_meaning, &
      map_end_grid, map_end_inside, map_end_mu_range, map_end_failed, map_point, &
      special_meaning, map_point_meet, map_point_turn, map_point_end, map_point_fail

   public :: wa_version
   public :: gap_critical_type, gap_critical, gap_critical_sweep, gap_critical_values, &
      gap_critical_count, gap_critical_names
   public :: map_control_load, map_control_gap, map_control_both
   public :: gap_mechanisms, gap_mechanism_change, gap_mechanism_name
   public :: bem_law_type, lj_law, law_eval, law_potential, law_zero, law_peak
   public :: lj_problem, lj_auto_n, lj_zone_length, lj_max_unknowns, lj_max_auto_n
   public :: lj_path_type, lj_cycle_type, lj_paths, lj_cycle, lj_rigid_pull_off, &
      lj_profile, lj_stage_loading, &
      lj_stage_unloading, lj_stage_approach, lj_stage_retraction, lj_path_jump_start, &
      lj_path_jump_end, lj_path_full_contact_reached, lj_path_full_contact_left, lj_path_pull_off
   public :: lj_problem_type, lj_branch_type, lj_trace_options, lj_trace, lj_event_none, &
      lj_event_load_fold, lj_event_gap_fold, lj_event_full_contact, lj_event_contact, lj_event_end

end module wavyadhesion
