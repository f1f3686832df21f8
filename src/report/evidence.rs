//! A claim's evidence laid out as tables: details named `model: statistic` that several
//! models share become one model × percentile table (quantiles) and one statistic × model
//! table (everything else), instead of rows repeating the model's name. Numbers a Monte Carlo
//! study estimated carry the digits its trial count supports ([`super::values::shown_text`]).

use super::values::{sampled_text, value_text};
use crate::check::Role;
use crate::check::{ClaimResult, Quantity, Value};
use crate::numfmt::sig;

/// A table of formatted cells.
#[derive(Clone, Debug, PartialEq)]
pub struct Table {
    /// What the table shows.
    pub caption: String,
    /// The header of the first column.
    pub corner: String,
    /// The column headers.
    pub columns: Vec<String>,
    /// Each row: its header and one cell per column (empty when missing).
    pub rows: Vec<(String, Vec<String>)>,
}

/// The evidence of one claim as a reader sees it.
#[derive(Clone, Debug)]
pub struct Layout<'a> {
    /// Details shown one per row, in the checks' order.
    pub rows: Vec<&'a Quantity>,
    /// The per-model statistics as tables.
    pub tables: Vec<Table>,
    /// The trial count behind the claim's sampled numbers.
    pub trials: Option<u64>,
}

/// The column headers of a quantile statistic (`["5 %", "25 %", …]`), read from the typed
/// probabilities its cells carry; none for any other statistic.
fn percentiles(statistic: &str, typed: &[(String, Vec<f64>)]) -> Option<Vec<String>> {
    typed
        .iter()
        .find(|(s, _)| s == statistic)
        .map(|(_, ps)| ps.iter().map(|p| format!("{} %", sig(100.0 * p))).collect())
}

/// Lay out `c`'s evidence.
pub fn layout(c: &ClaimResult) -> Layout<'_> {
    let trials = super::values::trials_of(c);
    let details = &c.evidence.details;
    let split = |q: &Quantity| -> Option<(String, String)> {
        match &q.role {
            Role::Cell {
                model, statistic, ..
            } => Some((model.clone(), statistic.clone())),
            _ => None,
        }
    };
    // a model joins a table when it shares a statistic with another model
    let named: Vec<(String, String)> = details.iter().filter_map(split).collect();
    let shared = |model: &str, stat: &str| named.iter().any(|(m, s)| m != model && s == stat);
    let mut models: Vec<String> = Vec::new();
    for (m, s) in &named {
        if shared(m, s) && !models.contains(m) {
            models.push(m.clone());
        }
    }
    let entry = |q: &Quantity| matches!(q.role, Role::Entry { .. });
    let in_table = |q: &Quantity| entry(q) || split(q).is_some_and(|(m, _)| models.contains(&m));
    let rows: Vec<&Quantity> = details.iter().filter(|q| !in_table(q)).collect();
    let grouped: Vec<(String, String, &Value)> = details
        .iter()
        .filter(|q| in_table(q))
        .filter_map(|q| split(q).map(|(m, s)| (m, s, &q.value)))
        .collect();
    let mut typed: Vec<(String, Vec<f64>)> = Vec::new();
    for q in details {
        if let Role::Cell {
            statistic,
            percentiles,
            ..
        } = &q.role
            && !percentiles.is_empty()
            && !typed.iter().any(|(s, _)| s == statistic)
        {
            typed.push((statistic.clone(), percentiles.clone()));
        }
    }
    let mut tables = entry_tables(details, trials);
    if !models.is_empty() {
        tables.extend(quantile_tables(&models, &grouped, &typed, trials));
        if let Some(t) = statistic_table(&models, &grouped, &typed, trials) {
            tables.push(t);
        }
    }
    Layout {
        rows,
        tables,
        trials,
    }
}

/// The tables of [`Role::Entry`] details, each with its rows and columns in first-seen order.
fn entry_tables(details: &[Quantity], trials: Option<u64>) -> Vec<Table> {
    let mut tables: Vec<Table> = Vec::new();
    for q in details {
        let Role::Entry { table, row, column } = &q.role else {
            continue;
        };
        let at = match tables.iter().position(|t| &t.caption == table) {
            Some(i) => i,
            None => {
                tables.push(Table {
                    caption: table.clone(),
                    corner: String::new(),
                    columns: Vec::new(),
                    rows: Vec::new(),
                });
                tables.len() - 1
            }
        };
        let t = &mut tables[at];
        let col = t
            .columns
            .iter()
            .position(|c| c == column)
            .unwrap_or_else(|| {
                t.columns.push(column.clone());
                t.columns.len() - 1
            });
        let r = t
            .rows
            .iter()
            .position(|(h, _)| h == row)
            .unwrap_or_else(|| {
                t.rows.push((row.clone(), Vec::new()));
                t.rows.len() - 1
            });
        let cells = &mut t.rows[r].1;
        if cells.len() <= col {
            cells.resize(col + 1, String::new());
        }
        cells[col] = cell(&q.value, trials);
    }
    for t in &mut tables {
        let n = t.columns.len();
        t.rows
            .iter_mut()
            .for_each(|(_, c)| c.resize(n, String::new()));
    }
    tables
}

/// One model × percentile table per quantile statistic.
fn quantile_tables(
    models: &[String],
    grouped: &[(String, String, &Value)],
    typed: &[(String, Vec<f64>)],
    trials: Option<u64>,
) -> Vec<Table> {
    let mut stats: Vec<&str> = Vec::new();
    for (_, s, v) in grouped {
        if percentiles(s, typed).is_some()
            && matches!(v, Value::Reals { .. })
            && !stats.contains(&&**s)
        {
            stats.push(s);
        }
    }
    stats
        .into_iter()
        .filter_map(|stat| {
            let columns = percentiles(stat, typed)?;
            let rows = models
                .iter()
                .map(|m| {
                    let cells = grouped
                        .iter()
                        .find(|(gm, gs, _)| gm == m && gs == stat)
                        .and_then(|(_, _, v)| match v {
                            Value::Reals { values } if values.len() == columns.len() => Some(
                                values
                                    .iter()
                                    .map(|r| cell(&Value::real(r.0), trials))
                                    .collect(),
                            ),
                            _ => None,
                        })
                        .unwrap_or_else(|| vec![String::new(); columns.len()]);
                    (m.clone(), cells)
                })
                .collect();
            Some(Table {
                caption: stat.to_string(),
                corner: "model".into(),
                columns,
                rows,
            })
        })
        .collect()
}

fn cell(v: &Value, trials: Option<u64>) -> String {
    match trials {
        Some(n) => sampled_text(v, n),
        None => value_text(v),
    }
}

/// The statistics that are not quantile lists, one row each, one column per model.
fn statistic_table(
    models: &[String],
    grouped: &[(String, String, &Value)],
    typed: &[(String, Vec<f64>)],
    trials: Option<u64>,
) -> Option<Table> {
    let mut stats: Vec<&str> = Vec::new();
    for (_, s, v) in grouped {
        let quantiles = percentiles(s, typed).is_some() && matches!(v, Value::Reals { .. });
        if !quantiles && !stats.contains(&&**s) {
            stats.push(s);
        }
    }
    if stats.is_empty() {
        return None;
    }
    let rows = stats
        .iter()
        .map(|stat| {
            let cells = models
                .iter()
                .map(|m| {
                    grouped
                        .iter()
                        .find(|(gm, gs, _)| gm == m && gs == stat)
                        .map(|(_, _, v)| cell(v, trials))
                        .unwrap_or_default()
                })
                .collect();
            (stat.to_string(), cells)
        })
        .collect();
    Some(Table {
        caption: "per model".into(),
        corner: "statistic".into(),
        columns: models.to_vec(),
        rows,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::check::{Evidence, Power, Verdict};

    fn claim(details: Vec<Quantity>) -> ClaimResult {
        let mut e = Evidence::new("m");
        e.details = details;
        ClaimResult {
            id: "x".into(),
            claim: "x".into(),
            case: "c".into(),
            section: "2".into(),
            lines: "1".into(),
            quote: String::new(),
            verdict: Verdict::StatisticalHolds,
            printed: Vec::new(),
            computed: Vec::new(),
            tolerance: None,
            power: Power::exact_value("d"),
            correction: None,
            undecided: None,
            rests_on: Vec::new(),
            evidence: e,
        }
    }

    #[test]
    fn shared_statistics_become_tables_with_sampled_digits() {
        let c = claim(vec![
            Quantity::with_role("trials per model", Value::count(10_000), Role::Trials),
            Quantity::quantiles(
                "A",
                "5/50/95 % quantiles",
                &[0.05, 0.5, 0.95],
                &[0.0123456, 0.5, 1.23456],
            ),
            Quantity::cell("A", "mean over the trials", 0.2345678),
            Quantity::quantiles(
                "B",
                "5/50/95 % quantiles",
                &[0.05, 0.5, 0.95],
                &[0.01, 0.6, 2.0],
            ),
            Quantity::cell("B", "mean over the trials", 0.3),
            Quantity::cell("mutant", "lonely", 0.123456),
            // a printed run's error is a row of its own, whatever its name says
            Quantity::new("printed run: error", 0.0642088),
        ]);
        let l = layout(&c);
        assert_eq!(l.trials, Some(10_000));
        let names: Vec<&str> = l.rows.iter().map(|q| q.name.as_str()).collect();
        assert_eq!(
            names,
            ["trials per model", "mutant: lonely", "printed run: error"]
        );
        assert_eq!(l.tables.len(), 2);
        assert_eq!(l.tables[0].columns, ["5 %", "50 %", "95 %"]);
        assert_eq!(
            l.tables[0].rows[0],
            (
                "A".to_string(),
                vec!["0.0123".into(), "0.500".into(), "1.23".into()]
            )
        );
        assert_eq!(
            l.tables[1].rows,
            vec![(
                "mean over the trials".to_string(),
                vec!["0.235".to_string(), "0.300".to_string()]
            )]
        );
    }

    #[test]
    fn a_claim_without_models_keeps_its_rows() {
        let c = claim(vec![Quantity::new("a", 1.0), Quantity::new("b: c", 2.0)]);
        let l = layout(&c);
        assert_eq!(l.rows.len(), 2);
        assert!(l.tables.is_empty());
    }
}
