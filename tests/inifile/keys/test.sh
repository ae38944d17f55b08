# keys: whitespace around '=', empty values, case, repeated keys (-num, any section) and malformed lines.
. "$TEST_DIR/../lib.sh"
q -ini keys.ini -var K1
q -ini keys.ini -var K2
q -ini keys.ini -var EMPTY
q -ini keys.ini -var EMPTY2
q -ini keys.ini -var lower
q -ini keys.ini -var LOWER
q -ini keys.ini -var Lower
for n in 1 2 3 4 5; do q -ini keys.ini -var R -num $n; done
q -ini keys.ini -var R -sec A -num 2
q -ini keys.ini -var R -sec B -num 2
q -ini keys.ini -var R -sec B -num 3
for f in nosection noequal badtag digittag notag; do q -ini $f.ini -var X; done
