# continuation: a line ending in '\' joins the next one verbatim; comments swallow too; not on the last line.
. "$TEST_DIR/../lib.sh"
q -ini cont.ini -var APP
q -ini cont.ini -var TWO
q -ini cont.ini -var SWALLOWED
q -ini cont.ini -var AFTER
q -ini cont.ini -var TRAIL
q -ini last.ini -var X
