//! What the VM tells whoever watches it run: the [`Recorder`] interface, the
//! bytes a recorder holds, and the recorder of a run without a trace. The
//! trace's own recorder is in [`super::trace`]; the VM sees only this.

use super::types::{Type, Value};
use crate::schema::ElementRef;

/// Receives the VM's steps. `step` is called before the step changes any
/// variable, with the running frame's variables as they are, so a recorder
/// can snapshot them.
pub(crate) trait Recorder {
    fn step(&mut self, pc: u32, a: Value, b: Value, r: Value, variables: &[Value]);
    /// A frame starts running `routine` with these variables: the root
    /// frame before the first step, a call's right after the call's step.
    /// `initial` are the routine's initial variables, which most of them
    /// still are.
    fn enter(&mut self, routine: u32, variables: &[Value], initial: &[Value]);
    /// The innermost frame returned; its return step was recorded.
    fn leave(&mut self);
    /// A new empty array of `item`s, numbered in the order they are made.
    fn array_created(&mut self, item: Type);
    /// The step just recorded changed an array: item `index` went from
    /// `old` to `new`, or (`old` = `None`) `new` was appended.
    fn array_changed(&mut self, array: u32, index: u32, old: Option<Value>, new: Value);
    fn mark(&mut self, element: ElementRef);
    fn highlight(&mut self, element: ElementRef);
    /// Stores a message's text and returns its number.
    fn message(&mut self, text: String) -> u32;
    /// The bytes it holds for the run's memory budget: its messages' texts,
    /// and the rest.
    fn bytes(&self) -> Held;
}

/// What a [`Recorder`] holds, in bytes.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct Held {
    pub messages: usize,
    pub other: usize,
}

/// Keeps what a run without a trace reports: its marks, highlights and
/// messages.
#[derive(Default)]
pub(crate) struct OutputRecorder {
    pub marked: Vec<ElementRef>,
    pub highlighted: Vec<ElementRef>,
    pub messages: Vec<String>,
    held: Held,
}

impl Recorder for OutputRecorder {
    #[inline]
    fn step(&mut self, _pc: u32, _a: Value, _b: Value, _r: Value, _variables: &[Value]) {}

    #[inline]
    fn enter(&mut self, _routine: u32, _variables: &[Value], _initial: &[Value]) {}

    #[inline]
    fn leave(&mut self) {}

    #[inline]
    fn array_created(&mut self, _item: Type) {}

    #[inline]
    fn array_changed(&mut self, _array: u32, _index: u32, _old: Option<Value>, _new: Value) {}

    fn mark(&mut self, element: ElementRef) {
        push_counted(&mut self.marked, element, &mut self.held.other);
    }

    fn highlight(&mut self, element: ElementRef) {
        push_counted(&mut self.highlighted, element, &mut self.held.other);
    }

    fn message(&mut self, text: String) -> u32 {
        self.held.messages += text.capacity();
        push_counted(&mut self.messages, text, &mut self.held.other);
        u32::try_from(self.messages.len() - 1).unwrap_or(u32::MAX)
    }

    fn bytes(&self) -> Held {
        self.held
    }
}

/// Appends `items` to `list`, adding what its buffer grew by to `held`: a
/// run's memory is counted as it is taken, not summed over every buffer.
pub(crate) fn extend_counted<T: Copy>(list: &mut Vec<T>, items: &[T], held: &mut usize) {
    let before = list.capacity();
    list.extend_from_slice(items);
    *held += (list.capacity() - before) * size_of::<T>();
}

pub(crate) fn push_counted<T>(list: &mut Vec<T>, item: T, held: &mut usize) {
    let before = list.capacity();
    list.push(item);
    *held += (list.capacity() - before) * size_of::<T>();
}
