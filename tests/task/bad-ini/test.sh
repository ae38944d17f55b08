#!/bin/bash
# milltask refuses unusable INI files with one message per problem (file:line where there is
# one) and exit status 1, before it touches NML, HAL or motion.
for ini in no-joints.ini too-many.ini bad-values.ini syntax.ini missing.ini; do
    milltask -ini "$ini" 2>&1
    echo "exit $?"
done
milltask 2>&1
echo "exit $?"
