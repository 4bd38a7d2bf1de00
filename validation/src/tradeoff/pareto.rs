//! The Pareto front of a sweep: the settings no other setting beats on
//! both cost and error.

/// The indices of the points `(cost, error)` on the front, in order of
/// increasing cost: each point such that no other has a cost and an error
/// both no greater, one of them smaller. Equal points are all on it.
/// Points with a NaN coordinate are never on it.
pub fn front(points: &[(f64, f64)]) -> Vec<usize> {
    let mut order: Vec<usize> = (0..points.len())
        .filter(|&i| !points[i].0.is_nan() && !points[i].1.is_nan())
        .collect();
    // By cost, then error: a point is on the front exactly when its error
    // is below every error seen at a strictly smaller cost, or equal to
    // the best at its own cost.
    order.sort_by(|&a, &b| {
        points[a]
            .0
            .total_cmp(&points[b].0)
            .then(points[a].1.total_cmp(&points[b].1))
    });
    let mut on = Vec::new();
    let mut best = f64::INFINITY;
    let mut last: Option<(f64, f64)> = None;
    for i in order {
        let p = points[i];
        if p.1 < best || last == Some(p) {
            on.push(i);
            best = best.min(p.1);
            last = Some(p);
        }
    }
    on
}

#[cfg(test)]
mod tests {
    use super::front;
    use proptest::prelude::*;

    #[test]
    fn the_front_of_a_known_set() {
        // (1, 5) (2, 3) (3, 4) (4, 1) (5, 1): (3, 4) is beaten by (2, 3),
        // (5, 1) by (4, 1).
        let points = [(3.0, 4.0), (1.0, 5.0), (5.0, 1.0), (2.0, 3.0), (4.0, 1.0)];
        assert_eq!(front(&points), vec![1, 3, 4]);
    }

    #[test]
    fn ties_and_nan() {
        // Same cost, worse error: beaten. Identical points: both on it.
        assert_eq!(front(&[(1.0, 2.0), (1.0, 1.0)]), vec![1]);
        assert_eq!(front(&[(1.0, 1.0), (1.0, 1.0)]), vec![0, 1]);
        // Same error, higher cost: beaten.
        assert_eq!(front(&[(2.0, 1.0), (1.0, 1.0)]), vec![1]);
        assert_eq!(front(&[(f64::NAN, 0.0), (1.0, 1.0)]), vec![1]);
        assert!(front(&[]).is_empty());
    }

    proptest! {
        /// The definition, checked point by point against the quadratic
        /// search: on the front exactly when no point dominates it.
        #[test]
        fn the_front_is_the_undominated_points(
            points in proptest::collection::vec((0u8..8, 0u8..8), 0..24)
        ) {
            let points: Vec<(f64, f64)> =
                points.iter().map(|&(c, e)| (f64::from(c), f64::from(e))).collect();
            let dominated = |i: usize| points.iter().any(|q| {
                let p = points[i];
                q.0 <= p.0 && q.1 <= p.1 && (q.0 < p.0 || q.1 < p.1)
            });
            let mut want: Vec<usize> = (0..points.len()).filter(|&i| !dominated(i)).collect();
            let mut got = front(&points);
            want.sort_unstable();
            got.sort_unstable();
            prop_assert_eq!(got, want);
        }
    }
}
