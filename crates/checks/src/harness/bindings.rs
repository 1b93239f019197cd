//! The disk's constants bound to the paper's symbols.

/// The disk's constants under the paper's names: the mass $m$, gravity $g$, the radius $a$ and
/// the inertia factor $k$ of eq 18 ($I_{11} = 2kma^2$, $I_{22} = I_{33} = kma^2$).
pub fn disk_constants(d: &physics::disk::Disk) -> paper::Bindings<f64> {
    paper::Bindings::new()
        .scalar("m", d.m)
        .scalar("g", d.g)
        .scalar("a", d.a)
        .scalar("k", d.k)
}
