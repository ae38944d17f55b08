# lines: CRLF and CR-only line ends, trailing blanks, a missing final newline, NUL bytes, empty files.
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
