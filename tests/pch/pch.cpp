// The owner of the tests' precompiled header (tests/CMakeLists.txt, t2_test_pch): nothing else.
