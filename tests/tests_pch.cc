// Carries the precompiled tests.h that every test program reuses (see
// tests/CMakeLists.txt); it defines nothing.
