//! The rule texts of the requirements, read from `spec/requirements/*.toml` when the tool is
//! built (so that `check` quotes the catalog as it is, never a copy).

use std::collections::HashMap;
use std::sync::OnceLock;

/// The requirement files, embedded at build time.
const FILES: [(&str, &str); 5] = [
    (
        "s5.toml",
        include_str!("../../../spec/requirements/s5.toml"),
    ),
    (
        "iec.toml",
        include_str!("../../../spec/requirements/iec.toml"),
    ),
    (
        "counter.toml",
        include_str!("../../../spec/requirements/counter.toml"),
    ),
    (
        "time.toml",
        include_str!("../../../spec/requirements/time.toml"),
    ),
    (
        "cli.toml",
        include_str!("../../../spec/requirements/cli.toml"),
    ),
];

fn table() -> &'static HashMap<String, String> {
    static TABLE: OnceLock<HashMap<String, String>> = OnceLock::new();
    TABLE.get_or_init(|| {
        let mut map = HashMap::new();
        for (_, text) in FILES {
            let Ok(doc) = text.parse::<toml::Table>() else {
                continue;
            };
            let Some(toml::Value::Array(reqs)) = doc.get("requirement") else {
                continue;
            };
            for r in reqs {
                if let (Some(toml::Value::String(id)), Some(toml::Value::String(rule))) =
                    (r.get("id"), r.get("rule"))
                {
                    map.insert(id.clone(), rule.clone());
                }
            }
        }
        map
    })
}

/// The rule text of requirement `id`, if the catalog has it.
pub fn rule(id: &str) -> Option<&'static str> {
    table().get(id).map(String::as_str)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_file_parses_and_has_rules() {
        for (name, text) in FILES {
            let doc = text
                .parse::<toml::Table>()
                .unwrap_or_else(|e| panic!("{name}: {e}"));
            assert!(doc.contains_key("requirement"), "{name}");
        }
        assert!(rule("IEC-EXPIRY-01").is_some_and(|r| r.contains("ET >= PT")));
        assert!(rule("CLI-RUN-01").is_some());
        assert_eq!(rule("NO-SUCH-01"), None);
    }
}
