# hal_procs_lib.tcl and util_lib.tcl against a small HAL made here
source [file join $::env(HALLIB_DIR) hal_procs_lib.tcl]
source [file join $::env(HALLIB_DIR) util_lib.tcl]
loadrt threads name1=servo-thread period1=1000000
loadrt scale names=a,b
loadrt lowpass names=c
addf a servo-thread
addf b servo-thread
addf c servo-thread
net ab a.out => b.in c.in
puts "pin_exists a.out=[pin_exists a.out] a.o=[pin_exists a.o] nosuch=[pin_exists nosuch]"
puts "a.out [is_connected a.out sig] ($sig), b.in [is_connected b.in], b.out [is_connected b.out]"
connection_info info b.in
puts "b.in owner-is-number=[string is integer $info(owner)] type=$info(type) dir=$info(direction) sig=$info(signame)"
get_netlist readers writer ios ab
puts "ab: writer=$writer readers=[lsort $readers] io=$ios"
puts "thread_info -> '[thread_info t]' threads=$t(threadnames) period=$t(servo-thread,period) b=$t(servo-thread,b) last=$t(servo-thread,index,last)"
puts "find: [file tail [find_file_in_hallib_path LIB:core_sim.hal]] [find_file_in_hallib_path procs.tcl]"
if {[catch {find_file_in_hallib_path nosuch.hal} msg]} { puts "find error: $msg" }
set ::env(KINS_KINEMATICS) "trivkins coordinates=XYYZ"
set ::env(TRAJ_COORDINATES) "XYYZ"
puts "joint of z=[joint_number_for_axis z] y=[joint_number_for_axis Y]"
if {[catch {joint_number_for_axis a} msg]} { puts "error: $msg" }
set ::env(KINS_KINEMATICS) corexykins
if {[catch {joint_number_for_axis x} msg]} { puts "error: $msg" }
