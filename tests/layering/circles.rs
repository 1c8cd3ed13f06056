//! The circles of a file graph, and how they are told to a developer.
//!
//! The files that reach one another form strongly connected groups (Tarjan's algorithm). Each
//! group is told as circles that together pass along every dependency inside it: for each
//! dependency a → b not yet on a told circle, the shortest way from b back to a closes one.
//! Breaking every dependency told, or enough of them that no told circle is left whole, is what
//! the layering asks.

use std::collections::{BTreeMap, BTreeSet, VecDeque};
use std::path::{Path, PathBuf};

use crate::resolve::Graph;

/// A circle of files: each names the next, and the last names the first.
pub type Circle = Vec<PathBuf>;

/// The circles of `graph`, each starting at its first file in path order.
pub fn circles(graph: &Graph) -> Vec<Circle> {
    let mut found = BTreeSet::new();
    for group in groups(graph) {
        let inside = |f: &PathBuf| group.contains(f);
        let mut covered: BTreeSet<(PathBuf, PathBuf)> = BTreeSet::new();
        for a in &group {
            for b in graph[a].keys().filter(|b| inside(b)) {
                if covered.contains(&(a.clone(), b.clone())) {
                    continue;
                }
                let Some(back) = shortest(graph, b, a, &group) else {
                    continue;
                };
                let mut circle: Circle = std::iter::once(a.clone()).chain(back).collect();
                circle.pop();
                for (x, y) in circle.iter().zip(circle.iter().cycle().skip(1)) {
                    covered.insert((x.clone(), y.clone()));
                }
                let start = (0..circle.len())
                    .min_by_key(|&i| &circle[i])
                    .expect("a circle has files");
                circle.rotate_left(start);
                found.insert(circle);
            }
        }
    }
    found.into_iter().collect()
}

/// The groups of two files or more that reach one another (Tarjan's strongly connected
/// components).
fn groups(graph: &Graph) -> Vec<BTreeSet<PathBuf>> {
    struct State<'g> {
        graph: &'g Graph,
        next: usize,
        index: BTreeMap<&'g PathBuf, usize>,
        low: BTreeMap<&'g PathBuf, usize>,
        stack: Vec<&'g PathBuf>,
        on_stack: BTreeSet<&'g PathBuf>,
        out: Vec<BTreeSet<PathBuf>>,
    }
    fn visit<'g>(s: &mut State<'g>, v: &'g PathBuf) {
        s.index.insert(v, s.next);
        s.low.insert(v, s.next);
        s.next += 1;
        s.stack.push(v);
        s.on_stack.insert(v);
        let graph = s.graph;
        for (w, _) in graph.get(v).into_iter().flatten() {
            if !graph.contains_key(w) {
                continue;
            }
            if !s.index.contains_key(w) {
                visit(s, w);
                let low = s.low[v].min(s.low[w]);
                s.low.insert(v, low);
            } else if s.on_stack.contains(w) {
                let low = s.low[v].min(s.index[w]);
                s.low.insert(v, low);
            }
        }
        if s.low[v] == s.index[v] {
            let mut group = BTreeSet::new();
            while let Some(w) = s.stack.pop() {
                s.on_stack.remove(w);
                group.insert(w.clone());
                if w == v {
                    break;
                }
            }
            if group.len() > 1 {
                s.out.push(group);
            }
        }
    }
    let mut s = State {
        graph,
        next: 0,
        index: BTreeMap::new(),
        low: BTreeMap::new(),
        stack: Vec::new(),
        on_stack: BTreeSet::new(),
        out: Vec::new(),
    };
    for v in graph.keys() {
        if !s.index.contains_key(v) {
            visit(&mut s, v);
        }
    }
    s.out
}

/// The shortest way from `from` to `to` inside `group`, `from` and `to` included.
fn shortest(
    graph: &Graph,
    from: &PathBuf,
    to: &PathBuf,
    group: &BTreeSet<PathBuf>,
) -> Option<Vec<PathBuf>> {
    let mut before: BTreeMap<&PathBuf, &PathBuf> = BTreeMap::new();
    let mut queue = VecDeque::from([from]);
    let mut seen = BTreeSet::from([from]);
    while let Some(x) = queue.pop_front() {
        if x == to {
            let mut way = vec![x.clone()];
            let mut at = x;
            while let Some(&b) = before.get(at) {
                way.push(b.clone());
                at = b;
            }
            way.reverse();
            return Some(way);
        }
        for y in graph[x].keys().filter(|y| group.contains(*y)) {
            if seen.insert(y) {
                before.insert(y, x);
                queue.push_back(y);
            }
        }
    }
    None
}

/// A circle told: the chain `a → b → c → a`, then for each file the line where it names the
/// next and the path written there. Paths are shown relative to `base`.
pub fn tell(circle: &Circle, graph: &Graph, base: &Path) -> String {
    let show = |p: &Path| p.strip_prefix(base).unwrap_or(p).display().to_string();
    let mut chain: Vec<String> = circle.iter().map(|f| show(f)).collect();
    chain.push(show(&circle[0]));
    let mut out = format!("  {}\n", chain.join(" → "));
    for (a, b) in circle.iter().zip(circle.iter().cycle().skip(1)) {
        let naming = &graph[a][b];
        out += &format!(
            "    {}:{} names {}: `{}`\n",
            show(a),
            naming.line,
            show(b),
            naming.text
        );
    }
    out
}
