component message "Print a message when a HAL bit changes";
pin in bit trigger = FALSE "The message is printed when this pin changes to the level selected by edge";
pin in bit force = FALSE "A rising edge prints the message again while trigger is at the selected level";
param rw bit edge = TRUE "TRUE: print on a rising edge of trigger; FALSE: print on a falling edge (active-low input)";
modparam dummy messages "Comma-separated list of messages, one per instance in order, inside one pair of quotes. Extra messages are ignored; too few messages refuse the load.";
variable int prev_trigger;
variable int prev_force;
variable int msg_index;
option extra_setup yes;
function _ "Watch trigger and force and print the message on an edge";
license "GPL";
author "OpenEMC";
description """
Each instance owns one text from the messages module parameter and prints it
at error level (so graphical front ends show it) whenever trigger changes to
the active level chosen by edge.  Nothing is printed in any other cycle.
""";
examples """
loadrt message names=oil-low,drive-fault messages="Slideway oil low,Spindle drive fault"
makes two instances, oil-low and drive-fault, each with its own text.  Add
each to a thread with addf, connect its trigger pin to the fault signal and
set oil-low.edge to FALSE when the signal is active low.
""";
;;
#define MESSAGE_MAX 64

static char *messages[MESSAGE_MAX];
RTAPI_MP_ARRAY_STRING(messages, MESSAGE_MAX, "Comma-separated messages, one per instance");

/* Print this instance's message on the selected edge of trigger or a rising edge of force. */
FUNCTION(_)
{
    int trig = trigger, frc = force, active = trig == (edge ? 1 : 0);
    int fire = (trig != prev_trigger && active) || (frc && !prev_force && active);
    prev_trigger = trig;
    prev_force = frc;
    if (fire) rtapi_print_msg(RTAPI_MSG_ERR, "%s\n", messages[msg_index]);
}

/* Bind instance extra_arg to its message; a missing message refuses the load. */
EXTRA_SETUP()
{
    if (extra_arg >= MESSAGE_MAX || !messages[extra_arg] || !messages[extra_arg][0]) {
        rtapi_print_msg(RTAPI_MSG_ERR, "MESSAGE: ERROR: no message for instance %ld (%s); "
                        "give one per instance in messages=\"...\"\n", extra_arg, prefix);
        return -EINVAL;
    }
    msg_index = (int)extra_arg;
    return 0;
}
