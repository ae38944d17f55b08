component corexy_by_hal "CoreXY kinematics done in HAL, between identity joints and the two motors";
pin in float j0_motor_pos_cmd "Joint 0 (X) position command from motion";
pin in float j1_motor_pos_cmd "Joint 1 (Y) position command from motion";
pin out float j0_motor_pos_fb "Joint 0 (X) position feedback to motion: alpha-fb + beta-fb";
pin out float j1_motor_pos_fb "Joint 1 (Y) position feedback to motion: alpha-fb - beta-fb";
pin out float alpha_cmd "Alpha motor command: (j0 + j1) / 2";
pin out float beta_cmd "Beta motor command: (j0 - j1) / 2";
pin in float alpha_fb "Alpha motor position feedback";
pin in float beta_fb "Beta motor position feedback";
function _;
description """Use with identity kinematics (trivkins) for joints 0 and 1: the motion
commands of the two joints are turned into the commands of the two belt motors of a
CoreXY machine, and the motor feedback is turned back into joint feedback, as LinuxCNC's
corexy_by_hal does: alpha = (j0 + j1) / 2, beta = (j0 - j1) / 2, and back j0 = alpha + beta,
j1 = alpha - beta.""";
license "GPL";
author "OpenEMC";
;;
double a = alpha_fb, b = beta_fb;
alpha_cmd = 0.5 * (j0_motor_pos_cmd + j1_motor_pos_cmd);
beta_cmd = 0.5 * (j0_motor_pos_cmd - j1_motor_pos_cmd);
j0_motor_pos_fb = a + b;
j1_motor_pos_fb = a - b;
