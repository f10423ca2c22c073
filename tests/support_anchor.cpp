// Keeps every tfd_test_support_<layer> library non-empty; shared test helpers live in
// tests/support/ (tests/CMakeLists.txt says which layer each belongs to).
