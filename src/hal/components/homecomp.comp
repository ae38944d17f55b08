component homecomp "Template of a homing module (HOMEMOD): the homing API with skeleton behaviour";
description """
A copy of this component, renamed and extended, can replace the default homing module
(\\fB[EMCMOT]HOMEMOD\\fR or \\fBlinuxcnc -m\\fR).  As shipped, a joint counts as homed while
\\fBmotion.allow-sim-homed\\fR is TRUE (the default), else while its \\fBjoint.N.home-sw-in\\fR is
TRUE; no joint ever moves.  The module exports every function of the homing API that motion
resolves at load.
""";
pin out bit is_module = 1 "Always TRUE: this is a homing module";
modparam dummy home_parms "Free-form parameters for a custom homing module";
option homemod yes;
option extra_setup yes;
license "GPL";
author "OpenEMC";
;;
#include "hal/components/homecomp_api.h"
