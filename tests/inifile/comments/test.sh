# comments: '#'/';' lines are comments, '#'/';' inside a value belong to it, only '#INCLUDE<blank>' at column 1 is an include.
. "$TEST_DIR/../lib.sh"
vars comments.ini X
q -ini comments.ini -var Y -sec A
vars comments.ini Z INCLUDE
