use std::collections::BTreeSet;

use crate::algebra::{canonical_blades, grade, Blade};
use crate::spec::{grade_type_name, TypeRequest};

/// An index into [`Types`]: 0 is the scalar, 1..=n the grades, then `Even`, `Odd`,
/// `Multivector`, then user types.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct TypeId(pub usize);

impl TypeId {
    /// The plain scalar type.
    pub const SCALAR: TypeId = TypeId(0);

    /// The struct of grade `k` (1..=n).
    pub fn grade(k: usize) -> TypeId {
        TypeId(k)
    }

    /// `Even` in dimension `n`.
    pub fn even(n: usize) -> TypeId {
        TypeId(n + 1)
    }

    /// `Odd` in dimension `n`.
    pub fn odd(n: usize) -> TypeId {
        TypeId(n + 2)
    }

    /// `Multivector` in dimension `n`.
    pub fn multivector(n: usize) -> TypeId {
        TypeId(n + 3)
    }
}

/// What a type is; decides its name, aliases and which methods make sense.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TypeKind {
    Scalar,
    Grade(usize),
    Even,
    Odd,
    Multivector,
    User,
}

/// One candidate type: its name and its components in canonical order.
#[derive(Clone, Debug)]
pub struct TypeDef {
    pub name: String,
    pub blades: Vec<Blade>,
    pub kind: TypeKind,
}

/// The result type of an operation.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Output {
    /// Zero for every input: the zero-sized `Zero`.
    Zero,
    /// A real type (possibly the scalar).
    Type(TypeId),
}

/// Every type an algebra can use, built-in and user-named.
#[derive(Clone)]
pub struct Types {
    dimension: usize,
    defs: Vec<TypeDef>,
}

impl Types {
    /// The scalar, the grade types, `Even`, `Odd`, `Multivector` and the user's types.
    pub fn new(dimension: usize, requests: &[TypeRequest]) -> Types {
        let all = canonical_blades(dimension);
        let with = |keep: &dyn Fn(Blade) -> bool| -> Vec<Blade> {
            all.iter().copied().filter(|&b| keep(b)).collect()
        };
        let mut defs = vec![TypeDef {
            name: "Scalar".into(),
            blades: vec![0],
            kind: TypeKind::Scalar,
        }];
        for k in 1..=dimension {
            defs.push(TypeDef {
                name: grade_type_name(k).into(),
                blades: with(&|b| grade(b) as usize == k),
                kind: TypeKind::Grade(k),
            });
        }
        defs.push(TypeDef {
            name: "Even".into(),
            blades: with(&|b| grade(b).is_multiple_of(2)),
            kind: TypeKind::Even,
        });
        defs.push(TypeDef {
            name: "Odd".into(),
            blades: with(&|b| grade(b) % 2 == 1),
            kind: TypeKind::Odd,
        });
        defs.push(TypeDef {
            name: "Multivector".into(),
            blades: all.clone(),
            kind: TypeKind::Multivector,
        });
        for request in requests {
            if let TypeRequest::User { name, blades } = request {
                let set: BTreeSet<Blade> = blades.iter().copied().collect();
                let ordered = all.iter().copied().filter(|b| set.contains(b)).collect();
                defs.push(TypeDef {
                    name: name.clone(),
                    blades: ordered,
                    kind: TypeKind::User,
                });
            }
        }
        Types { dimension, defs }
    }

    /// The algebra's dimension.
    pub fn dimension(&self) -> usize {
        self.dimension
    }

    /// The definition of a type.
    pub fn get(&self, id: TypeId) -> &TypeDef {
        &self.defs[id.0]
    }

    /// The built-in struct types, in declaration order.
    pub fn builtin_ids(&self) -> Vec<TypeId> {
        (1..=self.dimension + 3).map(TypeId).collect()
    }

    /// The id of a user type by name.
    pub fn id_by_name(&self, name: &str) -> TypeId {
        TypeId(self.defs.iter().position(|d| d.name == name).unwrap_or(0))
    }

    /// The grades a type has components in.
    pub fn grades_of(&self, id: TypeId) -> Vec<usize> {
        let set: BTreeSet<usize> = self
            .get(id)
            .blades
            .iter()
            .map(|&b| grade(b) as usize)
            .collect();
        set.into_iter().collect()
    }

    /// The type with the fewest components that holds every given blade; ties go to the
    /// earlier type (scalar, grades, Even, Odd, Multivector, user types).
    pub fn smallest_holding(&self, blades: impl IntoIterator<Item = Blade>) -> Output {
        self.smallest_holding_preferring(blades, &[])
    }

    /// As [`Types::smallest_holding`], but a tie goes first to the `preferred` types (the
    /// operands), so that `Odd * s` stays `Odd` where `Odd` and `Vector` coincide.
    pub fn smallest_holding_preferring(
        &self,
        blades: impl IntoIterator<Item = Blade>,
        preferred: &[TypeId],
    ) -> Output {
        let wanted: BTreeSet<Blade> = blades.into_iter().collect();
        for &id in preferred {
            let def = self.get(id);
            if def.blades.len() == wanted.len() && wanted.iter().all(|b| def.blades.contains(b)) {
                return Output::Type(id);
            }
        }
        if wanted.is_empty() {
            return Output::Zero;
        }
        let mut best: Option<(usize, TypeId)> = None;
        for (i, def) in self.defs.iter().enumerate() {
            if wanted.iter().all(|b| def.blades.contains(b))
                && best.is_none_or(|(len, _)| def.blades.len() < len)
            {
                best = Some((def.blades.len(), TypeId(i)));
            }
        }
        // Multivector holds every blade, so there is always a best.
        Output::Type(best.map_or(TypeId::multivector(self.dimension), |(_, id)| id))
    }
}
