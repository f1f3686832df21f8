//! How a verdict was reached: the method and the supporting values, each with its role.

use serde::Serialize;

use super::{Quantity, Role, Value};

/// How a verdict was reached.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Evidence {
    /// The method.
    pub method: String,
    /// Supporting values, in order.
    pub details: Vec<Quantity>,
}

impl Evidence {
    /// Evidence with a method and no details yet.
    pub fn new(method: &str) -> Self {
        Evidence {
            method: method.into(),
            details: Vec::new(),
        }
    }

    /// One cell of a table: `statistic` of `model`.
    pub fn with_cell(mut self, model: &str, statistic: &str, value: impl Into<Value>) -> Self {
        self.details.push(Quantity::cell(model, statistic, value));
        self
    }

    /// One cell listing the quantiles of `model` at the probabilities `percentiles`.
    pub fn with_quantiles(
        mut self,
        model: &str,
        statistic: &str,
        percentiles: &[f64],
        values: &[f64],
    ) -> Self {
        self.details
            .push(Quantity::quantiles(model, statistic, percentiles, values));
        self
    }

    /// One detail in `role`.
    pub fn with_role(mut self, name: &str, value: impl Into<Value>, role: Role) -> Self {
        self.details.push(Quantity::with_role(name, value, role));
        self
    }

    /// One entry of the table `table`.
    pub fn with_entry(
        mut self,
        table: &str,
        row: &str,
        column: &str,
        value: impl Into<Value>,
    ) -> Self {
        self.details
            .push(Quantity::entry(table, row, column, value));
        self
    }

    /// Add a detail.
    pub fn with(mut self, name: &str, value: impl Into<Value>) -> Self {
        self.details.push(Quantity::new(name, value));
        self
    }
}
