//! The faster-and-more-accurate front: the settings no other setting beats on both counts.
//!
//! A setting `q` *dominates* a setting `p` when `q` is at least as fast and at least as
//! accurate as `p` and strictly better in one of the two. The front (the Pareto front of time
//! against error) is the set of settings that nothing dominates: for each of them, anything
//! faster is less accurate and anything more accurate is slower. Two settings with exactly the
//! same time and error do not dominate each other, so both stay on the front.

/// The indices of the points (time, error) on the front, in order of increasing time (then
/// increasing error, then index). Smaller is better on both axes. A point with a coordinate
/// that is not a number is never on the front and dominates nothing.
pub fn front(points: &[(f64, f64)]) -> Vec<usize> {
    let valid = |p: &(f64, f64)| !p.0.is_nan() && !p.1.is_nan();
    let dominates =
        |q: &(f64, f64), p: &(f64, f64)| q.0 <= p.0 && q.1 <= p.1 && (q.0 < p.0 || q.1 < p.1);
    let mut on: Vec<usize> = (0..points.len())
        .filter(|&i| valid(&points[i]))
        .filter(|&i| {
            !points
                .iter()
                .filter(|q| valid(q))
                .any(|q| dominates(q, &points[i]))
        })
        .collect();
    on.sort_by(|&a, &b| {
        let (pa, pb) = (points[a], points[b]);
        pa.0.total_cmp(&pb.0)
            .then(pa.1.total_cmp(&pb.1))
            .then(a.cmp(&b))
    });
    on
}

#[cfg(test)]
mod tests {
    use super::front;

    #[test]
    fn empty_has_an_empty_front() {
        assert_eq!(front(&[]), Vec::<usize>::new());
    }

    #[test]
    fn a_single_point_is_its_own_front() {
        assert_eq!(front(&[(3.0, 7.0)]), vec![0]);
    }

    #[test]
    fn hand_made_set_with_a_known_front() {
        // time, error: the front runs 0 → 2 → 4 → 5; 1, 3 and 6 are each beaten by one of
        // them on both counts
        let points = [
            (1.0, 10.0), // 0: fastest
            (2.0, 12.0), // 1: slower and worse than 0
            (3.0, 5.0),  // 2
            (4.0, 6.0),  // 3: slower and worse than 2
            (5.0, 2.0),  // 4
            (9.0, 0.5),  // 5: most accurate
            (9.5, 3.0),  // 6: slower and worse than 4 and 5
        ];
        assert_eq!(front(&points), vec![0, 2, 4, 5]);
    }

    #[test]
    fn the_order_is_by_time_whatever_the_input_order() {
        let points = [(9.0, 0.5), (4.0, 6.0), (1.0, 10.0), (5.0, 2.0), (3.0, 5.0)];
        assert_eq!(front(&points), vec![2, 4, 3, 0]);
    }

    #[test]
    fn equal_time_keeps_only_the_more_accurate() {
        // same time, less error: 1 dominates 0 (at least as good on both, better on one)
        assert_eq!(front(&[(2.0, 4.0), (2.0, 3.0)]), vec![1]);
    }

    #[test]
    fn equal_error_keeps_only_the_faster() {
        assert_eq!(front(&[(2.0, 3.0), (1.0, 3.0), (5.0, 1.0)]), vec![1, 2]);
    }

    #[test]
    fn exact_duplicates_both_stay() {
        assert_eq!(front(&[(2.0, 3.0), (1.0, 4.0), (2.0, 3.0)]), vec![1, 0, 2]);
    }

    #[test]
    fn duplicates_of_a_dominated_point_all_go() {
        assert_eq!(front(&[(2.0, 3.0), (3.0, 4.0), (3.0, 4.0)]), vec![0]);
    }

    #[test]
    fn one_point_better_on_both_counts_is_the_whole_front() {
        let points = [(5.0, 5.0), (1.0, 1.0), (2.0, 3.0), (4.0, 1.5)];
        assert_eq!(front(&points), vec![1]);
    }

    #[test]
    fn not_a_number_is_never_on_the_front_and_beats_nothing() {
        let points = [(f64::NAN, 0.0), (1.0, 2.0), (0.5, f64::NAN), (2.0, 1.0)];
        assert_eq!(front(&points), vec![1, 3]);
    }
}
