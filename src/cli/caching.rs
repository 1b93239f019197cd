//! The `--no-cache` and `--cache-dir` options of the commands that keep results between runs
//! (`check` and `report`), flattened into each.

use ::report::cache::Cache;
use std::path::PathBuf;

/// Where the results that depend on nothing but the program are kept between runs.
#[derive(clap::Args)]
pub struct Caching {
    /// Computes everything, keeping nothing between runs. Without it, what depends on nothing
    /// but the program (the squeeze film's dissipation number of eqs 76-84; in the report also
    /// the toy's stored peer runs and scans) is computed once per build and kept in the cache
    /// folder; the output is the same to the byte either way.
    #[arg(long)]
    pub no_cache: bool,
    /// The cache folder (default: $XDG_CACHE_HOME/rolling-disk, or ~/.cache/rolling-disk).
    #[arg(long, value_name = "DIR", conflicts_with = "no_cache")]
    pub cache_dir: Option<PathBuf>,
}

impl Caching {
    /// The cache these options name: none with `--no-cache`, else `--cache-dir` or the user's.
    pub fn cache(&self) -> Option<Cache> {
        if self.no_cache {
            None
        } else {
            self.cache_dir.clone().map(Cache::at).or_else(Cache::user)
        }
    }
}
