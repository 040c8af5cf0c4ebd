//! `RuleSet`, the set the explanations carry, against a plain model: a `BTreeSet` of positions
//! in `Rule::ALL` (the catalog order, which the set's iteration promises). The explanation
//! drivers use `contains`, `with` and `union`; this covers every other operation a user of
//! `plc_timers::rule` has, on random sets that span the whole catalog.

use std::collections::BTreeSet;

use plc_timers::rule::{Rule, RuleSet};
use proptest::prelude::*;

/// A random subset of the catalog as the model (positions in `Rule::ALL`).
fn model() -> impl Strategy<Value = BTreeSet<usize>> {
    prop::collection::btree_set(0..Rule::COUNT, 0..=Rule::COUNT)
}

/// The set of the model's rules, built with `insert` only.
fn build(m: &BTreeSet<usize>) -> RuleSet {
    let mut s = RuleSet::EMPTY;
    for &i in m {
        s.insert(Rule::ALL[i]);
    }
    s
}

/// The model's rules in catalog order.
fn rules(m: &BTreeSet<usize>) -> Vec<Rule> {
    m.iter().map(|&i| Rule::ALL[i]).collect()
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(2_000))]

    /// Membership, size and emptiness after `insert`, and the other builders agree with it.
    #[test]
    fn insert_contains_len(m in model()) {
        let s = build(&m);
        for (i, r) in Rule::ALL.iter().enumerate() {
            prop_assert_eq!(s.contains(*r), m.contains(&i), "contains({}) of {:?}", r, m);
        }
        prop_assert_eq!(s.len(), m.len());
        prop_assert_eq!(s.is_empty(), m.is_empty());
        let with = m.iter().fold(RuleSet::EMPTY, |s, &i| s.with(Rule::ALL[i]));
        prop_assert_eq!(with, s, "with");
        let with_if = Rule::ALL
            .iter()
            .enumerate()
            .fold(RuleSet::EMPTY, |s, (i, r)| s.with_if(m.contains(&i), *r));
        prop_assert_eq!(with_if, s, "with_if");
        prop_assert_eq!(rules(&m).into_iter().collect::<RuleSet>(), s, "from_iter");
        let unions = m.iter().fold(RuleSet::EMPTY, |s, &i| s.union(RuleSet::from(Rule::ALL[i])));
        prop_assert_eq!(unions, s, "union of From<Rule>");
        // Adding a rule the set has already changes nothing (a toggle would remove it).
        for &i in &m {
            let r = Rule::ALL[i];
            prop_assert_eq!(s.with(r), s, "with({}) again", r);
            prop_assert_eq!(s.with_if(true, r), s, "with_if({}) again", r);
            let mut again = s;
            again.insert(r);
            prop_assert_eq!(again, s, "insert({}) again", r);
            prop_assert_eq!(s.union(RuleSet::of(r)), s, "union with {} again", r);
        }
    }

    /// Iteration gives the rules in catalog order, with an exact size hint at every step.
    #[test]
    fn iteration_in_catalog_order(m in model()) {
        let s = build(&m);
        let want = rules(&m);
        let mut it = s.iter();
        for (k, r) in want.iter().enumerate() {
            let left = want.len() - k;
            prop_assert_eq!(it.size_hint(), (left, Some(left)));
            prop_assert_eq!(it.len(), left);
            prop_assert_eq!(it.next(), Some(*r));
        }
        prop_assert_eq!(it.size_hint(), (0, Some(0)));
        prop_assert_eq!(it.next(), None);
        prop_assert_eq!(s.into_iter().collect::<Vec<_>>(), want);
    }

    /// Union, difference and subset against the model's.
    #[test]
    fn set_algebra(a in model(), b in model()) {
        let (sa, sb) = (build(&a), build(&b));
        prop_assert_eq!(sa.union(sb), build(&a.union(&b).copied().collect()));
        prop_assert_eq!(sa.difference(sb), build(&a.difference(&b).copied().collect()));
        prop_assert_eq!(sa.is_subset(sb), a.is_subset(&b));
        prop_assert!(sa.difference(sb).is_subset(sa));
        prop_assert!(sa.is_subset(sa.union(sb)));
    }

    /// `Display` lists the IDs separated by `, ` in catalog order; `Debug` is a set of the IDs.
    #[test]
    fn text_forms(m in model()) {
        let s = build(&m);
        let ids: Vec<&str> = rules(&m).iter().map(|r| r.id()).collect();
        prop_assert_eq!(s.to_string(), ids.join(", "));
        let quoted: Vec<String> = ids.iter().map(|id| format!("{id:?}")).collect();
        prop_assert_eq!(format!("{s:?}"), format!("{{{}}}", quoted.join(", ")));
    }
}

/// Each rule shows as its ID, and `from_id` finds it; edge cases of the set's width.
#[test]
fn every_rule_by_id() {
    for r in Rule::ALL {
        assert_eq!(r.to_string(), r.id(), "Display of {r:?}");
        assert_eq!(Rule::from_id(r.id()), Some(r));
        assert_eq!(RuleSet::of(r).len(), 1);
        assert_eq!(RuleSet::of(r).iter().next(), Some(r));
    }
    assert_eq!(Rule::from_id(""), None);
    assert_eq!(
        Rule::from_id("iec-expiry-01"),
        None,
        "IDs are matched exactly"
    );
    let all: RuleSet = Rule::ALL.into_iter().collect();
    assert_eq!(all.len(), Rule::COUNT);
    assert_eq!(all.iter().collect::<Vec<_>>(), Rule::ALL);
    assert!(RuleSet::EMPTY.is_empty() && RuleSet::default().is_empty());
    assert_eq!(RuleSet::EMPTY.to_string(), "");
    assert_eq!(format!("{:?}", RuleSet::EMPTY), "{}");
}
