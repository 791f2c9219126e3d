// The translation unit that owns the GoogleTest executables' shared precompiled header
// (tests/CMakeLists.txt: rodvv_test_pch); every test target reuses the header it builds.
