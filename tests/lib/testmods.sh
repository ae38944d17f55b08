# testmods.sh: sourced by tests that load test-only realtime modules (built into objects/testlib/, not
# rtlib/). Makes a private RTLIB_DIR holding every module of rtlib/ plus the test modules, and stops a
# master left from before (it would use the old directory). Call tm_cleanup when done (it also stops
# this test's master).
tm_top=${EMC2_HOME:-$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)}
tm_lib=$(mktemp -d /tmp/testmods.XXXXXX)
ln -s "$tm_top"/rtlib/*.so "$tm_top"/objects/testlib/*.so "$tm_lib"/
export RTLIB_DIR=$tm_lib
realtime stop >/dev/null 2>&1

# tm_cleanup: stop the master and remove the private directory
tm_cleanup() {
    realtime stop >/dev/null 2>&1
    rm -rf "$tm_lib"
}
