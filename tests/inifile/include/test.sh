# include: #INCLUDE paths (relative to the including file, ~/), section continuity, recursion, depth, missing files.
. "$TEST_DIR/../lib.sh"
q -ini main.ini -var INHERITED -sec A
q -ini main.ini -var DEEP -sec A
q -ini main.ini -var CONTINUED -sec B
q -ini main.ini -var FROM_PART -sec B
q -ini main.ini -var TAB -sec C
for f in self loop1 missing; do vars $f.ini X; done
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
printf 'HOMEVAL = from home\n' > "$work/home.ini"
printf '[H]\n#INCLUDE ~/home.ini\n' > "$work/tilde.ini"
HOME=$work q -ini "$work/tilde.ini" -var HOMEVAL
env -u HOME inivar -ini "$work/tilde.ini" -var HOMEVAL 2>&1 | sed "s|$work/||" || true
# f0 includes f1 ... includes fN: 16 files open at once are refused, 15 load
for i in $(seq 0 15); do printf '[S%d]\n#INCLUDE f%d.ini\n' $i $((i + 1)) > "$work/f$i.ini"; done
printf 'END = 16\n' > "$work/f16.ini"
(cd "$work" && q -ini f0.ini -var END)
printf '[S14]\nEND = 14\n' > "$work/f14.ini"
(cd "$work" && q -ini f0.ini -var END)
# "#INCLUDE" without a file name, with only blanks or glued to the name is an error
for line in '#INCLUDE' '#INCLUDE   ' '#INCLUDEfoo.ini'; do
    printf '[S]\n%s\nX = 1\n' "$line" > "$work/bad.ini"
    (cd "$work" && q -ini bad.ini -var X)
done
