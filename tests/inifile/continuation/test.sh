# continuation: a line ending in '\' joins the next one verbatim; comments swallow too; not on the last line.
. "$TEST_DIR/../lib.sh"
vars cont.ini APP TWO SWALLOWED AFTER TRAIL
vars last.ini X
