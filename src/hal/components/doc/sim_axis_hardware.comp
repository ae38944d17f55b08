component sim_axis_hardware "Simulated home and limit switches from axis positions";
modparam dummy count "Number of instances (default 1)";
modparam dummy names "Names of the instances (instead of count)";
option singleton yes;
license "GPL";
author "OpenEMC";
description """Channels X, X2, Y, Y2, Z, A, U and V. For channel L (p = Lcurrent-pos):
Lhomesw-out is TRUE within Lhomesw-hyst/2 of Lhomesw-pos; Lmaxsw-out while
Lmaxsw-lower + limit-offset < p < Lmaxsw-upper; Lminsw-out while Lminsw-lower < p <
Lminsw-upper - limit-offset; Lbothsw-out is either limit while no channel is homing
(Lhoming); the -homesw-out pins OR in the home switch (never written for channel A).
homesw-all is any home switch while homing, limitsw-all any Lbothsw-out,
limitsw-homesw-all either. Function NAME.update.""";
