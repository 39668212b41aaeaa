// Fixture of verification.spec-orphans (not compiled): one case is named by the spec, one is not.
BOOST_AUTO_TEST_CASE(listed_case) {}
BOOST_AUTO_TEST_CASE(unlisted_case) {}
