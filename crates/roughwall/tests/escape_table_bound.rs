//! A process keeps each distinct escape table for its life, so it takes at most
//! `MAX_DISTINCT_TABLES` of them besides the built-in one: one more is a one-line error
//! (through the C library: `RW_INVALID_PARAMETER`), and memory stays bounded however many
//! walls a host builds and frees. (Its own test file: the bound is per process.)

use roughwall::calibrated::MAX_DISTINCT_TABLES;
use roughwall::calibrated::{EscapeCounts, EscapeTable};
use roughwall::{WallModel, WallParams};

#[test]
fn distinct_escape_tables_are_bounded_per_process() {
    let table = |k: usize| EscapeTable::from_counts(EscapeCounts::default(), &format!("t{k}"));
    let mut kept = Vec::new();
    for k in 0..MAX_DISTINCT_TABLES {
        kept.push(table(k).intern().expect("within the bound"));
    }
    // The same tables again, and the built-in one, cost nothing.
    for (k, t) in kept.iter().enumerate() {
        assert!(std::ptr::eq(table(k).intern().unwrap(), *t));
    }
    assert!(EscapeTable::builtin().clone().intern().is_ok());
    let e = table(MAX_DISTINCT_TABLES).intern().unwrap_err().to_string();
    assert!(
        e.contains("more than 16 distinct escape tables") && !e.contains('\n'),
        "{e}"
    );
    // A wall model given one table too many is refused with that message.
    let counts = EscapeTable::builtin().counts().clone();
    let text = EscapeTable::from_counts(counts, "one too many").to_csv();
    let refused = WallModel::new(&WallParams {
        delta_xi_deg: 2.5,
        delta_zeta_deg: 7.5,
        model: Some("calibrated".into()),
        escape_table: Some(text),
        ..Default::default()
    })
    .unwrap_err()
    .to_string();
    assert!(refused.contains("distinct escape tables"), "{refused}");
}
