# comments: '#'/';' lines are comments, '#'/';' inside a value belong to it, only '#INCLUDE<blank>' at column 1 includes.
. "$TEST_DIR/../lib.sh"
q -ini comments.ini -var X
q -ini comments.ini -var Y -sec A
q -ini comments.ini -var Z
q -ini comments.ini -var INCLUDE
