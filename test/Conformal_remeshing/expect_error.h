// Copyright (c) 2026 CGAL Conformal Remeshing contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The tests' check that a call fails the way the library documents: it throws
// CGAL::Conformal_remeshing::Error with the expected code, and its message contains each expected
// fragment.

#ifndef CGAL_CONFORMAL_REMESHING_TEST_EXPECT_ERROR_H
#define CGAL_CONFORMAL_REMESHING_TEST_EXPECT_ERROR_H

#include <CGAL/Conformal_remeshing/Error.h>

#include <gtest/gtest.h>

#include <initializer_list>
#include <string>

namespace test_support {

template <typename Call>
void expect_error(const Call& call, CGAL::Conformal_remeshing::Error_code code,
                  std::initializer_list<std::string> message_fragments = {})
{
  try
  {
    call();
    ADD_FAILURE() << "no exception, expected: " << CGAL::Conformal_remeshing::error_message(code);
  }
  catch(const CGAL::Conformal_remeshing::Error& e)
  {
    EXPECT_EQ(e.code(), code) << e.what();
    for(const std::string& fragment : message_fragments)
      EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
  }
}

} // namespace test_support

#endif // CGAL_CONFORMAL_REMESHING_TEST_EXPECT_ERROR_H
