# escapes: every escape form of a value, improper escapes (warning) and the malformed ones (error).
. "$TEST_DIR/../lib.sh"
for k in SIMPLE OCTAL HEX EDGE U4 U8 PAIR TRAILBS; do
    echo "-- $k"
    inivar -ini esc.ini -var $k 2> /dev/null | od -An -c
done
vars esc.ini IMPROPER
for f in nul-octal nul-u bad-x lone-surrogate bad-utf8 too-big short-u; do vars $f.ini X; done
