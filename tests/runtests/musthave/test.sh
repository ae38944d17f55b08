# musthave: a test runs only when every token is a HAVE_ define of src/config.h.
. "$TEST_DIR/../lib.sh"
have=$(sed -n 's/^#define HAVE_\([A-Za-z0-9_]*\).*/\1/p' "$EMC2_HOME/src/config.h" | head -n 1)
test -n "$have"
fixture a-have 'echo x' x
echo "$have" > "$TREE/a-have/musthave"
fixture b-missing 'echo x' x
printf '%s\nNO_SUCH_FEATURE_XYZ\n' "$have" > "$TREE/b-missing/musthave"
run_runner .
