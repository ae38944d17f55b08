#!/bin/bash
# halui refuses bad command lines and INI files with a message naming file, line and key,
# and exits 1 before it joins HAL.
unset INI_FILE_NAME
export LC_ALL=C
run() {
    echo "== halui $*"
    halui "$@" 2>&1
    echo "exit $?"
}
printf '[KINS]\nKINEMATICS = trivkins\n' > no-joints.ini
printf '[KINS]\nJOINTS = 20\n' > many-joints.ini
printf '[KINS]\nJOINTS = 3\n[TRAJ]\nSPINDLES = nine\n' > bad-spindles.ini
printf '[KINS\nJOINTS = 3\n' > syntax.ini
printf '[KINS]\nJOINTS = 3\n' > good.ini
run
run -ini
run -ini nosuch.ini
run -ini syntax.ini
run -ini no-joints.ini
run -ini many-joints.ini
run -ini bad-spindles.ini
run -ini good.ini --frobnicate
echo "== halui --help"
halui --help | head -1; echo "exit ${PIPESTATUS[0]}"
rm -f no-joints.ini many-joints.ini bad-spindles.ini syntax.ini good.ini
