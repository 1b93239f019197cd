//! Study results kept between runs: a study whose result depends only on the program and on
//! inputs it names (the toy's stored peer runs and scans, nothing of the paper) is computed once
//! per build and read back afterwards, so the report's bytes are the same from a cold cache as
//! from a warm one.
//!
//! An entry is one file, `STUDY-KEY.cbor`, in the cache's folder. Its key is the SHA-256 of the
//! entry format's version, the tool's version, the running program's identity (its path, size,
//! modification time and inode: a rebuilt program is a new build) and the study's own inputs.
//! The file holds a header (a magic line, the format's version, the key, the payload's length
//! and SHA-256) before the payload; an entry whose header or payload does not match, one cut
//! short, or one of another format or build is never trusted: the study is computed again and
//! the entry rewritten. Entries are written to a temporary file renamed into place, so a reader
//! never sees half an entry.

use sha2::{Digest, Sha256};
use std::fs;
use std::path::{Path, PathBuf};

/// The entry format's version: changes whenever the header's layout or a payload's encoding
/// does, so that no entry of another format is read.
pub const FORMAT: u32 = 1;

/// The first bytes of every entry.
const MAGIC: &[u8; 19] = b"rolling-disk cache\n";

/// Entries of one study kept at once (several builds, such as the program and its tests, may
/// share a cache folder); older ones are removed when a new one is written.
const KEPT_PER_STUDY: usize = 4;

/// A folder of study results kept between runs.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Cache {
    dir: PathBuf,
}

/// What became of one study's lookup.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Lookup {
    /// A valid entry was read.
    Hit,
    /// No entry for this build and these inputs.
    Missing,
    /// An entry was there but did not pass its checks (cut short, altered, another format).
    Invalid,
}

impl Cache {
    /// The cache in `dir` (created when the first entry is written).
    pub fn at(dir: impl Into<PathBuf>) -> Self {
        Self { dir: dir.into() }
    }

    /// The user's cache folder: `$XDG_CACHE_HOME/rolling-disk`, or `$HOME/.cache/rolling-disk`;
    /// `None` when neither variable names an absolute path.
    pub fn user() -> Option<Self> {
        let absolute = |v: &str| {
            std::env::var_os(v)
                .map(PathBuf::from)
                .filter(|p| p.is_absolute())
        };
        absolute("XDG_CACHE_HOME")
            .or_else(|| absolute("HOME").map(|h| h.join(".cache")))
            .map(|d| Self::at(d.join("rolling-disk")))
    }

    /// The cache's folder.
    pub fn dir(&self) -> &Path {
        &self.dir
    }

    /// The key of `study`'s result for `inputs` in this build; `None` when the running program
    /// cannot be identified (then nothing is cached).
    pub fn key(study: &str, inputs: &[u8]) -> Option<[u8; 32]> {
        let build = build_identity()?;
        let mut h = Sha256::new();
        for part in [
            &FORMAT.to_le_bytes()[..],
            crate::TOOL_VERSION.as_bytes(),
            &build,
            study.as_bytes(),
            inputs,
        ] {
            h.update((part.len() as u64).to_le_bytes());
            h.update(part);
        }
        Some(h.finalize().into())
    }

    fn path(&self, study: &str, key: &[u8; 32]) -> PathBuf {
        self.dir.join(format!("{study}-{}.cbor", hex(key)))
    }

    /// The payload stored under `study` and `key`, with what the lookup found.
    pub fn get(&self, study: &str, key: &[u8; 32]) -> (Lookup, Option<Vec<u8>>) {
        match fs::read(self.path(study, key)) {
            Err(_) => (Lookup::Missing, None),
            Ok(bytes) => match payload(&bytes, key) {
                Some(p) => (Lookup::Hit, Some(p.to_vec())),
                None => (Lookup::Invalid, None),
            },
        }
    }

    /// Stores `payload` under `study` and `key`, replacing any entry there, and removes the
    /// study's oldest entries beyond the few kept.
    pub fn put(&self, study: &str, key: &[u8; 32], payload: &[u8]) -> std::io::Result<()> {
        let path = self.path(study, key);
        let name = path
            .file_name()
            .and_then(|n| n.to_str())
            .unwrap_or_default();
        files::kept::store(&self.dir, name, &entry(key, payload))?;
        let own = |n: &str| is_entry_of(Path::new(n), study);
        files::kept::prune(&self.dir, own, KEPT_PER_STUDY - 1, &path);
        Ok(())
    }
}

/// Whether `path` is named as an entry of `study`: `STUDY-` and 64 hex digits, `.cbor`.
fn is_entry_of(path: &Path, study: &str) -> bool {
    path.file_name()
        .and_then(|n| n.to_str())
        .and_then(|n| {
            n.strip_prefix(study)?
                .strip_prefix('-')?
                .strip_suffix(".cbor")
        })
        .is_some_and(|k| k.len() == 64 && k.bytes().all(|b| b.is_ascii_hexdigit()))
}

/// The running program's identity: its path, size, modification time and inode.
fn build_identity() -> Option<Vec<u8>> {
    let exe = std::env::current_exe().ok()?;
    let meta = fs::metadata(&exe).ok()?;
    let mtime = meta
        .modified()
        .ok()?
        .duration_since(std::time::UNIX_EPOCH)
        .ok()?;
    let mut id = exe.to_string_lossy().into_owned().into_bytes();
    id.extend(meta.len().to_le_bytes());
    id.extend(mtime.as_nanos().to_le_bytes());
    #[cfg(unix)]
    {
        use std::os::unix::fs::MetadataExt;
        id.extend(meta.ino().to_le_bytes());
        id.extend(meta.dev().to_le_bytes());
    }
    Some(id)
}

/// An entry's bytes: magic, format, key, the payload's length and SHA-256, the payload.
fn entry(key: &[u8; 32], payload: &[u8]) -> Vec<u8> {
    let mut out = Vec::with_capacity(payload.len() + 100);
    out.extend_from_slice(MAGIC);
    out.extend_from_slice(&FORMAT.to_le_bytes());
    out.extend_from_slice(key);
    out.extend_from_slice(&(payload.len() as u64).to_le_bytes());
    out.extend_from_slice(&Sha256::digest(payload));
    out.extend_from_slice(payload);
    out
}

/// The payload of an entry's bytes, when its magic, format, key, length and hash all match.
fn payload<'a>(bytes: &'a [u8], key: &[u8; 32]) -> Option<&'a [u8]> {
    let rest = bytes.strip_prefix(&MAGIC[..])?;
    let rest = rest.strip_prefix(&FORMAT.to_le_bytes()[..])?;
    let rest = rest.strip_prefix(&key[..])?;
    let (len, rest) = rest.split_first_chunk::<8>()?;
    let (hash, body) = rest.split_first_chunk::<32>()?;
    let ok = u64::from_le_bytes(*len) == body.len() as u64 && Sha256::digest(body)[..] == hash[..];
    ok.then_some(body)
}

fn hex(bytes: &[u8]) -> String {
    bytes.iter().map(|b| format!("{b:02x}")).collect()
}

/// `value` as CBOR, which keeps every `f64` to the bit.
pub fn encode<T: serde::Serialize>(value: &T) -> Result<Vec<u8>, String> {
    let mut out = Vec::new();
    ciborium::into_writer(value, &mut out).map_err(|e| e.to_string())?;
    Ok(out)
}

/// A value read back from [`encode`]'s bytes.
pub fn decode<T: serde::de::DeserializeOwned>(bytes: &[u8]) -> Result<T, String> {
    ciborium::from_reader(bytes).map_err(|e| e.to_string())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn folder(name: &str) -> PathBuf {
        let d = std::env::temp_dir().join(format!(
            "rolling-disk-cache-test-{name}-{}",
            std::process::id()
        ));
        let _ = fs::remove_dir_all(&d);
        d
    }

    #[test]
    fn an_entry_is_read_back_as_written() {
        let c = Cache::at(folder("back"));
        let key = Cache::key("toy", b"inputs").unwrap();
        assert_eq!(c.get("toy", &key), (Lookup::Missing, None));
        c.put("toy", &key, b"payload").unwrap();
        assert_eq!(c.get("toy", &key), (Lookup::Hit, Some(b"payload".to_vec())));
        let _ = fs::remove_dir_all(c.dir());
    }

    #[test]
    fn other_inputs_or_another_study_have_another_key() {
        let k = Cache::key("toy", b"a").unwrap();
        assert_ne!(k, Cache::key("toy", b"b").unwrap());
        assert_ne!(k, Cache::key("friction", b"a").unwrap());
        assert_eq!(k, Cache::key("toy", b"a").unwrap());
    }

    #[test]
    fn an_altered_cut_or_foreign_entry_is_never_trusted() {
        let c = Cache::at(folder("altered"));
        let key = Cache::key("toy", b"x").unwrap();
        c.put("toy", &key, b"the toy's result").unwrap();
        let path = c.path("toy", &key);
        let good = fs::read(&path).unwrap();
        // One bit of the payload flipped, the payload cut short, the format's version changed,
        // the entry stored under another key, and an empty file: each is invalid.
        let mut flipped = good.clone();
        *flipped.last_mut().unwrap() ^= 1;
        let cut = good[..good.len() - 3].to_vec();
        let mut format = good.clone();
        format[MAGIC.len()] ^= 0xff;
        let other = entry(&Cache::key("toy", b"y").unwrap(), b"the toy's result");
        for bad in [flipped, cut, format, other, Vec::new()] {
            fs::write(&path, &bad).unwrap();
            assert_eq!(c.get("toy", &key), (Lookup::Invalid, None));
        }
        let _ = fs::remove_dir_all(c.dir());
    }

    #[test]
    fn only_a_few_entries_of_a_study_are_kept_and_no_other_file_is_touched() {
        let c = Cache::at(folder("prune"));
        fs::create_dir_all(c.dir()).unwrap();
        let other = c.dir().join("notes.txt");
        fs::write(&other, "mine").unwrap();
        let keys: Vec<[u8; 32]> = (0..KEPT_PER_STUDY + 2)
            .map(|i| Cache::key("toy", &[i as u8]).unwrap())
            .collect();
        let friction = Cache::key("friction", b"").unwrap();
        c.put("friction", &friction, b"f").unwrap();
        for k in &keys {
            c.put("toy", k, b"t").unwrap();
            std::thread::sleep(std::time::Duration::from_millis(20));
        }
        let toys = fs::read_dir(c.dir())
            .unwrap()
            .filter(|e| is_entry_of(&e.as_ref().unwrap().path(), "toy"))
            .count();
        assert_eq!(toys, KEPT_PER_STUDY);
        assert_eq!(c.get("toy", keys.last().unwrap()).0, Lookup::Hit);
        assert_eq!(c.get("toy", &keys[0]).0, Lookup::Missing);
        assert_eq!(c.get("friction", &friction).0, Lookup::Hit);
        assert_eq!(fs::read_to_string(&other).unwrap(), "mine");
        let _ = fs::remove_dir_all(c.dir());
    }

    #[test]
    fn cbor_keeps_every_float_to_the_bit() {
        let xs = vec![
            0.1,
            1.0 / 3.0,
            f64::MIN_POSITIVE,
            5e-324,
            -0.0,
            f64::MAX,
            f64::INFINITY,
            std::f64::consts::PI,
        ];
        let back: Vec<f64> = decode(&encode(&xs).unwrap()).unwrap();
        assert_eq!(
            xs.iter().map(|x| x.to_bits()).collect::<Vec<_>>(),
            back.iter().map(|x| x.to_bits()).collect::<Vec<_>>()
        );
        let nan: f64 = decode(&encode(&f64::NAN).unwrap()).unwrap();
        assert!(nan.is_nan());
    }
}
