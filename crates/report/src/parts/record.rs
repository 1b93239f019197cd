//! The parts' records in `report.json`: one object keyed by part name, in the report's order,
//! each part's record written by the part ([`Part::record`]) and its schema given by the part
//! ([`Part::record_schema`]), so that a new part's numbers reach the JSON with its row in
//! [`PARTS`] and nothing else.

use super::PARTS;
use crate::error::ReportError;
use crate::results::Results;
use schemars::{json_schema, JsonSchema, Schema, SchemaGenerator};
use serde::ser::SerializeMap;
use serde::{Serialize, Serializer};
use serde_json::Value;
use std::borrow::Cow;
use std::fmt;
use std::sync::Arc;

/// A part's record: any serializable value, written with its own fields in their own order.
pub type Record = Arc<dyn erased_serde::Serialize + Send + Sync>;

/// The records of the parts whose studies were computed, in the report's order.
#[derive(Clone, Default)]
pub struct PartRecords(pub Vec<(&'static str, Record)>);

impl PartRecords {
    /// The records of every part in [`PARTS`] that has one for `results`.
    pub fn of(results: &Results) -> Result<Self, ReportError> {
        let mut records = Vec::new();
        for p in PARTS {
            if let Some(r) = p.record(results)? {
                records.push((p.name(), r));
            }
        }
        Ok(Self(records))
    }

    /// The records as JSON values, by part.
    pub fn values(&self) -> Vec<(&'static str, Option<Value>)> {
        self.0
            .iter()
            .map(|(n, r)| (*n, serde_json::to_value(&**r).ok()))
            .collect()
    }
}

impl fmt::Debug for PartRecords {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_map().entries(self.values()).finish()
    }
}

/// Equal when the same parts write the same JSON.
impl PartialEq for PartRecords {
    fn eq(&self, other: &Self) -> bool {
        self.values() == other.values()
    }
}

impl Serialize for PartRecords {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        let mut map = serializer.serialize_map(Some(self.0.len()))?;
        for (name, record) in &self.0 {
            map.serialize_entry(name, &**record)?;
        }
        map.end()
    }
}

impl JsonSchema for PartRecords {
    fn schema_name() -> Cow<'static, str> {
        "PartRecords".into()
    }

    fn json_schema(generator: &mut SchemaGenerator) -> Schema {
        let properties: serde_json::Map<String, Value> = PARTS
            .iter()
            .map(|p| (p.name().to_string(), p.record_schema(generator).into()))
            .collect();
        json_schema!({
            "description": "Each part's record, keyed by the part's name, in the report's order; \
                            a part whose studies were not computed has none.",
            "type": "object",
            "properties": properties,
            "additionalProperties": false,
        })
    }
}

/// `value` as a part's record, `None` when it was not computed.
pub fn record_of<T: Serialize + Clone + Send + Sync + 'static>(
    value: Option<&T>,
) -> Result<Option<Record>, ReportError> {
    Ok(value.map(|v| Arc::new(v.clone()) as Record))
}
