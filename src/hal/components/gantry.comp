component gantry "Drive several joints from one axis, squaring them with their home switches";
pin out float joint.##.pos-cmd [7 : personality] "Position command for each joint";
pin in float joint.##.pos-fb [7 : personality] "Position feedback of each joint";
pin in bit joint.##.home [7 : personality] "Home switch of each joint";
pin out float joint.##.offset [7 : personality] "Offset of each joint from position-cmd, set while homing (for diagnostics)";
pin in float position-cmd "Position command from motion";
pin out float position-fb "Position feedback to motion";
pin out bit home "Combined home switch for motion: every joint switch while moving in the search direction, any switch otherwise";
pin out bit limit "TRUE while any joint home switch is active";
pin in float search-vel "HOME_SEARCH_VEL of the axis; its sign gives the direction towards the switches";
variable double prev_cmd;
variable double last_delta;
option default_personality 2;
option extra_setup yes;
function read "Combine the home switches and compute position-fb";
function write "Compute the joint position commands";
license "GPL";
author "OpenEMC";
description """
personality is the number of joints (1 to 7, default 2).  Each joint follows
position-cmd plus its own offset.  While position-cmd moves towards the home
switches (same sign as search-vel) a joint whose switch is active stops: its
offset absorbs the motion, so every joint ends up on its own switch and the
gantry is squared.  The offsets then stay until the next homing.  Add read
before motion and write after it in the servo thread.
""";
;;
/* Refuse a personality (joint count) below 1; the generated code refuses above 7. */
EXTRA_SETUP()
{
    (void)prefix;
    if (personality < 1) {
        rtapi_print_msg(RTAPI_MSG_ERR, "GANTRY: ERROR: personality (joint count) must be 1 to 7, got %d\n",
                        personality);
        return -EINVAL;
    }
    return 0;
}

/* Combine the switches: all of them while moving towards them, any of them otherwise. */
FUNCTION(read)
{
    int i, all = 1, any = 0;
    for (i = 0; i < personality; i++) {
        all = all && joint_home(i);
        any = any || joint_home(i);
    }
    home = (last_delta * search_vel > 0) ? all : any;
    limit = any;
    position_fb = joint_pos_fb(0) - joint_offset(0);
}

/* Joints on their switch hold still while the command moves towards the switches. */
FUNCTION(write)
{
    int i;
    double delta = position_cmd - prev_cmd;
    int towards = delta * search_vel > 0;
    for (i = 0; i < personality; i++) {
        if (towards && joint_home(i)) joint_offset(i) -= delta;
        joint_pos_cmd(i) = position_cmd + joint_offset(i);
    }
    prev_cmd = position_cmd;
    last_delta = delta;
}
