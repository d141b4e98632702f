#pragma once
// The shape functions and their derivatives at the points of a quadrature rule, tabulated once:
// every element of one shape and rule evaluates the same values at the same points in every sweep
// (the polynomials of quad_shape.hpp cost more than the products they feed). Shared between the
// elements of a model; built on first use for each distinct rule (thread-safe).
#include <memory>
#include <mutex>
#include <vector>

#include "libstruct/shape/triangle_quadrature.hpp"

namespace flexmoor::shape {

template <class Shape>
struct ShapeTable {
  std::vector<Eigen::Vector2d> points;  // the rule's, for recognising it
  std::vector<typename Shape::Values> values;
  std::vector<typename Shape::Derivatives> derivatives;

  explicit ShapeTable(const QuadratureRule2D& rule) : points(rule.points) {
    for (const Eigen::Vector2d& p : rule.points) {
      values.push_back(Shape::values(p.x(), p.y()));
      derivatives.push_back(Shape::derivatives(p.x(), p.y()));
    }
  }

  // The table of `rule`: one for all the elements that integrate with the same points.
  static std::shared_ptr<const ShapeTable> of(const QuadratureRule2D& rule) {
    static std::mutex mutex;
    static std::vector<std::shared_ptr<const ShapeTable>> tables;
    const std::lock_guard<std::mutex> lock(mutex);
    for (const auto& table : tables)
      if (table->points == rule.points) return table;
    tables.push_back(std::make_shared<const ShapeTable>(rule));
    return tables.back();
  }
};

}  // namespace flexmoor::shape
