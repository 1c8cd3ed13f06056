//! The octree: its cube follows a flat layer, and it numbers its objects leaf by leaf.

use whitted::accel::{Aabb, Octree};
use whitted::real::vec3;

/// The octree's cube starts at the scene's lower corner: a flat layer of objects (spheres on a
/// floor) is not cut through its middle by the first split, which would copy every object
/// into two cells. A cube centred on the layer does exactly that.
#[test]
fn a_flat_layer_is_not_copied_into_two_halves() {
    // 400 small boxes on a 20 × 20 grid, all in the layer 0 ≤ y ≤ 0.7
    let boxes: Vec<Aabb> = (0..400)
        .map(|i| {
            let (x, z) = ((i % 20) as f64 * 10.0, (i / 20) as f64 * 10.0);
            Aabb {
                min: vec3(x, 0.0, z),
                max: vec3(x, 0.0, z) + vec3(0.7, 0.7, 0.7),
            }
        })
        .collect();
    let tree = Octree::build(&boxes, 4);
    let (fullest, pairs) = tree.leaf_load();
    assert!(fullest <= 4, "{fullest}");
    // a box may still straddle a vertical split now and then, but not every box
    assert!(
        pairs < boxes.len() * 5 / 4,
        "{pairs} (object, leaf) pairs for 400 boxes"
    );
    // and wherever the layer lies: moved down by half its height, around y = 0, the same
    // boxes land in as many cells (the old cube, centred on the scene, gave 800 pairs here)
    let centred: Vec<Aabb> = boxes
        .iter()
        .map(|b| Aabb {
            min: b.min - vec3(0.0, 0.35, 0.0),
            max: b.max - vec3(0.0, 0.35, 0.0),
        })
        .collect();
    let (_, centred_pairs) = Octree::build(&centred, 4).leaf_load();
    assert_eq!(
        centred_pairs, pairs,
        "the cube follows the layer wherever it lies"
    );
}

/// The octree renumbers its objects in the order its leaves name them: the order it returns
/// is a permutation of the objects, neighbours in space get neighbouring numbers (a leaf's
/// objects are numbered one after another), and a second renumbering changes nothing.
#[test]
fn the_octree_numbers_its_objects_leaf_by_leaf() {
    // 256 unit boxes on a 16 × 16 grid, listed in an order that scatters neighbours: the
    // scene's k-th box sits at grid cell (37·k mod 256)
    let boxes: Vec<Aabb> = (0..256)
        .map(|k| {
            let cell = (k * 37) % 256;
            let (x, z) = ((cell % 16) as f64 * 2.0, (cell / 16) as f64 * 2.0);
            Aabb {
                min: vec3(x, 0.0, z),
                max: vec3(x + 1.0, 1.0, z + 1.0),
            }
        })
        .collect();
    let mut tree = Octree::build(&boxes, 4);
    let order = tree.renumber(boxes.len());
    let mut sorted = order.clone();
    sorted.sort_unstable();
    assert_eq!(sorted, (0..256).collect::<Vec<u32>>(), "a permutation");
    // each run of four consecutive new numbers is one leaf of four neighbours: within a
    // 4 × 4 patch of the grid (a cell of the octree), where the scene's order put them far
    // apart
    for run in order.chunks(4) {
        let at = |k: u32| {
            let c = (k as usize * 37) % 256;
            (c % 16, c / 16)
        };
        let (x0, z0) = at(run[0]);
        for &k in run {
            let (x, z) = at(k);
            assert!(x / 4 == x0 / 4 && z / 4 == z0 / 4, "{run:?}");
        }
    }
    assert_eq!(
        tree.renumber(boxes.len()),
        (0..256).collect::<Vec<u32>>(),
        "already in leaf order"
    );
}
