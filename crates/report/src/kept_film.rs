//! The squeeze film's dissipation number $I$ ([`SqueezeFilm`], the film of eqs 76-84) kept
//! between runs. It depends on nothing but the program (conforming finite elements on three
//! fixed grids, [`physics::model::film_bound`]) and its solution is the largest single cost of
//! `check`, so it is solved once per build and read back from the [`crate::cache`] afterwards,
//! every float to the bit: a run with the kept $I$ prints what a run that solves it prints.

use crate::cache::{decode, encode, Cache, Lookup};
use physics::model::air_film::{SqueezeFilm, COARSEST};

/// The entry's name in the cache folder.
pub const NAME: &str = "film";

/// The entry's key in this build: its inputs are the coarsest grid's cells (the others are
/// two and four times as fine); `None` when the running program cannot be identified.
fn key() -> Option<[u8; 32]> {
    Cache::key(NAME, &(COARSEST as u64).to_le_bytes())
}

/// Gives the process the $I$ that `cache` keeps for this build, when its entry is intact;
/// returns what the lookup found (an entry that passes the cache's checks but does not decode
/// is [`Lookup::Invalid`]).
pub fn restore(cache: &Cache) -> Lookup {
    let Some(key) = key() else {
        return Lookup::Missing;
    };
    let (lookup, bytes) = cache.get(NAME, &key);
    match bytes.map(|b| decode::<(f64, f64)>(&b)) {
        Some(Ok((coefficient, uncertainty))) => {
            SqueezeFilm::keep(SqueezeFilm {
                coefficient,
                uncertainty,
            });
            Lookup::Hit
        }
        Some(Err(_)) => Lookup::Invalid,
        None => lookup,
    }
}

/// Keeps the process's $I$ in `cache` when the process has solved it (a run that never needed
/// the film writes nothing).
pub fn store(cache: &Cache) -> std::io::Result<()> {
    let (Some(film), Some(key)) = (SqueezeFilm::settled(), key()) else {
        return Ok(());
    };
    let bytes = encode(&(film.coefficient, film.uncertainty)).map_err(std::io::Error::other)?;
    cache.put(NAME, &key, &bytes)
}

/// Runs `run` with the $I$ kept in `cache` (when there is one), and keeps the one `run` solved
/// when there was none; an entry that is not trusted, or a cache that cannot be written, is said
/// in `note` (the run's results are the same either way). Without a cache, just `run`.
pub fn around<T>(cache: Option<&Cache>, note: &dyn Fn(&str), run: impl FnOnce() -> T) -> T {
    let Some(cache) = cache else {
        return run();
    };
    let found = restore(cache);
    if found == Lookup::Invalid {
        note(&format!(
            "{NAME}: the cached result in {} did not pass its checks; computing it again",
            cache.dir().display()
        ));
    }
    let out = run();
    if found != Lookup::Hit {
        if let Err(e) = store(cache) {
            note(&format!(
                "{NAME}: could not keep the result in {} ({e}); it is computed every time",
                cache.dir().display()
            ));
        }
    }
    out
}
