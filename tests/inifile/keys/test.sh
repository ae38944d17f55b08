# keys: whitespace around '=', empty values, case, repeated keys (-num, any section) and malformed lines.
. "$TEST_DIR/../lib.sh"
vars keys.ini K1 K2 EMPTY EMPTY2 lower LOWER Lower
for n in 1 2 3 4 5; do q -ini keys.ini -var R -num $n; done
q -ini keys.ini -var R -sec A -num 2
q -ini keys.ini -var R -sec B -num 2
q -ini keys.ini -var R -sec B -num 3
for f in nosection noequal badtag digittag notag; do vars $f.ini X; done
