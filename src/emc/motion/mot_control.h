/* mot_control.h: the steps of the servo loop, each in the file named after it. */
#ifndef MOT_CONTROL_H
#define MOT_CONTROL_H

/* mot_kins.c */
void mot_kins_switch_input(void);
void mot_forward_kins_feedback(void);
/* mot_inputs.c */
void mot_process_inputs(void);
void mot_homing_inputs_update(void);
void mot_homing_outputs_apply(void);
/* mot_faults.c */
void mot_probe_input(void);
void mot_check_faults(void);
/* mot_modes.c */
void mot_mode_transitions(void);
/* mot_poscmd.c */
void mot_get_pos_cmds(void);
void mot_check_soft_limits(void);
/* mot_comp.c */
void mot_compensate(void);
/* mot_eoffset.c */
void mot_external_offsets(void);
void mot_eoffset_apply(EmcPose *pos);
/* mot_output.c */
void mot_output(void);
/* mot_status.c */
void mot_status_publish(void);
/* mot_spindle.c */
void mot_spindle_inputs(void);
void mot_spindle_outputs(void);
/* mot_init.c */
int mot_init_state(void);

#endif
