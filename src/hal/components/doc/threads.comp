component threads "Create up to three realtime threads";
modparam dummy name1 "Name of thread 1 (default thread1).";
modparam dummy period1 "Period of thread 1 in ns (default 1000000).";
modparam dummy name2 "Name of thread 2 (none by default).";
modparam dummy period2 "Period of thread 2 in ns (0 = no thread).";
modparam dummy name3 "Name of thread 3 (none by default).";
modparam dummy period3 "Period of thread 3 in ns (0 = no thread).";
modparam dummy fp1 "Accepted for compatibility and ignored (also fp2, fp3).";
option singleton yes;
license "GPL";
author "OpenEMC";
description """Registers the component threads (no pins, parameters or functions of its
own) and creates the threads in order, fastest first; a thread is skipped when its
name is empty or its period is not positive. Each thread brings the pseudo component
__NAME and NAME.time, NAME.tmax and NAME.threadbeat. Unloading threads removes only
the pseudo components; the threads run until the realtime environment stops.""";
examples """loadrt threads name1=fast period1=50000 name2=slow period2=1000000""";
