# lines: CRLF and CR-only line ends, trailing blanks, a missing final newline, NUL bytes, empty files, a BOM, endless input.
. "$TEST_DIR/../lib.sh"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
printf '[A]\r\nX = crlf value \r\nY=2\r\n' > crlf.ini
printf '[A]\rX = 1\rY = 2\r' > cr.ini
printf '[A]\nX = tabs and blanks\t \t\nY = no final newline' > blanks.ini
printf '[A]\nX = a\000b\n' > nul.ini
: > empty.ini
q -ini crlf.ini -var X | od -An -c
vars crlf.ini Y
vars cr.ini X
q -ini blanks.ini -var X | od -An -c
vars blanks.ini Y
vars nul.ini X
vars empty.ini X
# a UTF-8 byte order mark at the start of a file (and of an included one) is skipped
printf '\357\273\277[A]\nX = after bom\n#INCLUDE bom-inc.ini\n' > bom.ini
printf '\357\273\277Y = included after bom\n' > bom-inc.ini
vars bom.ini X Y
# a device that never ends (or a huge file) is refused instead of read forever
vars /dev/zero X
printf '[A]\n#INCLUDE /dev/zero\n' > zero-inc.ini
vars zero-inc.ini X
