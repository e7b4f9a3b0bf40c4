//! The lights, seen from the origin: each shape's χ² domain and swept parameter are its facts
//! ([`ShapeFacts::evidence`]): the sphere and the disk tested on a cap of directions that holds
//! them, the polygons on their own parameter squares.

use super::{Evidence, Facts, Kind};
use crate::registry::LightSampler;
use crate::verify::ShapeFacts;

impl Evidence for LightSampler {
    fn facts(&self) -> Facts {
        let (param, test) = self.0.evidence();
        Facts::new(Kind::Light, param, test)
    }
}
