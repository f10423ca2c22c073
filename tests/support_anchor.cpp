// Keeps tfd_test_support non-empty; shared test helpers live in tests/support/.
