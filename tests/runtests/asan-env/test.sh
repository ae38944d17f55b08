# asan-env: on a tree configured with --enable-asan, runtests puts python wrappers that preload
# the sanitizer runtimes first on PATH and sets the LeakSanitizer suppressions; else nothing.
exec python3 "$TEST_DIR/asanenv.py"
