# sections: case-sensitive names, merging of repeats, trailing text, and every malformed header.
. "$TEST_DIR/../lib.sh"
q -ini merge.ini -var MACHINE -sec EMC
q -ini merge.ini -var MACHINE -sec EMC -num 2
q -ini merge.ini -var MACHINE -sec emc
q -ini merge.ini -var MACHINE -num 3
q -ini merge.ini -var UNITS -sec TRAJ
q -ini merge.ini -var MACHINE -sec NOPE
for f in missing empty badchar digit; do vars $f.ini X; done
