# options: inivar's options, defaults, exit codes and error texts.
. "$TEST_DIR/../lib.sh"
echo "== defaults: -ini emc.ini, any section, -num 1"
q -var MACHINE
q -var MACHINE -num 2
q -sec X -var MACHINE
echo "== -tildeexpand"
HOME=/home/tester q -var HOMEPATH -tildeexpand
q -var HOMEPATH
HOME=/home/tester q -var TILDE_MID -tildeexpand
echo "== not found"
q -var NOPE
q -var MACHINE -sec NOPE
q -var MACHINE -sec X -num 2
echo "== usage errors"
q
q -sec EMC
q -var A -var B
q -sec A -sec B -var C
q -var MACHINE -tildeexpand -tildeexpand
q -var
q -var MACHINE -num
q -var MACHINE -x
q -var MACHINE extra
q -var MACHINE -num 0
q -var MACHINE -num -1
q -var MACHINE -num 1x
q -var MACHINE -num ''
echo "== file errors"
q -ini no-such.ini -var MACHINE
q -ini . -var MACHINE
q -ini /no/such/dir/x.ini -var MACHINE
