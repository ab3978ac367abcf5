//! Sets and maps over a triangulation's vertices as flat arrays, emptied in O(1): the
//! scratch space of SIG-AUTO's searches that run once per component or branch, where a hash
//! map per search costs more than the search (a scatter has tens of thousands of branches).

/// A set of vertices: marked in the current generation. Emptying starts a new generation.
pub(crate) struct VertexSet {
    stamp: Vec<u32>,
    generation: u32,
}

impl VertexSet {
    /// An empty set over `n` vertices.
    pub(crate) fn new(n: usize) -> VertexSet {
        VertexSet { stamp: vec![0; n], generation: 1 }
    }

    /// Empties the set.
    pub(crate) fn clear(&mut self) {
        if self.generation == u32::MAX {
            self.stamp.fill(0);
            self.generation = 0;
        }
        self.generation += 1;
    }

    /// Adds `v`; whether it was not in the set yet.
    pub(crate) fn insert(&mut self, v: u32) -> bool {
        let slot = &mut self.stamp[v as usize];
        let new = *slot != self.generation;
        *slot = self.generation;
        new
    }

    /// Whether `v` is in the set.
    pub(crate) fn contains(&self, v: u32) -> bool {
        self.stamp[v as usize] == self.generation
    }
}

/// A map from vertices to `u32` values: entries of the current generation.
pub(crate) struct VertexMap {
    keys: VertexSet,
    values: Vec<u32>,
}

impl VertexMap {
    /// An empty map over `n` vertices.
    pub(crate) fn new(n: usize) -> VertexMap {
        VertexMap { keys: VertexSet::new(n), values: vec![0; n] }
    }

    /// Empties the map.
    pub(crate) fn clear(&mut self) {
        self.keys.clear();
    }

    /// Sets `v`'s value when it has none; whether it had none.
    pub(crate) fn insert_new(&mut self, v: u32, value: u32) -> bool {
        let new = self.keys.insert(v);
        if new {
            self.values[v as usize] = value;
        }
        new
    }

    /// Sets `v`'s value.
    pub(crate) fn set(&mut self, v: u32, value: u32) {
        self.keys.insert(v);
        self.values[v as usize] = value;
    }

    /// `v`'s value, if it has one.
    pub(crate) fn get(&self, v: u32) -> Option<u32> {
        self.keys.contains(v).then(|| self.values[v as usize])
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn clearing_forgets_every_entry() {
        let mut set = VertexSet::new(4);
        assert!(set.insert(2) && !set.insert(2) && set.contains(2));
        set.clear();
        assert!(!set.contains(2) && set.insert(2));
        let mut map = VertexMap::new(4);
        assert!(map.insert_new(1, 7) && !map.insert_new(1, 8));
        assert_eq!(map.get(1), Some(7));
        map.set(1, 9);
        assert_eq!(map.get(1), Some(9));
        map.clear();
        assert_eq!(map.get(1), None);
    }

    #[test]
    fn the_last_generation_wraps_to_an_empty_set() {
        let mut set = VertexSet::new(2);
        set.generation = u32::MAX;
        set.insert(0);
        set.clear();
        assert!(!set.contains(0) && !set.contains(1));
    }
}
