// Fixture of verification.spec-orphans (not compiled): a program no entry names.
BOOST_AUTO_TEST_CASE(orphan) {}
