package org.kheperasim.sim.edit;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Collection;
import java.util.Deque;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Objects;
import java.util.Set;
import java.util.function.Consumer;
import java.util.function.Supplier;
import org.kheperasim.sim.arena.Arena;
import org.kheperasim.sim.engine.view.RobotView;

/**
 * The arena being edited, with its selection and an undo/redo stack. Every change goes through
 * {@link #apply}, which checks the result ({@link ArenaCheck}) and refuses an impossible one,
 * telling the refusal listener why. Not thread-safe: the window uses it on the event thread; tests
 * use it directly.
 */
public final class EditorModel {
    /** How many steps undo remembers. */
    public static final int UNDO_LIMIT = 200;

    private Arena arena;
    private Arena preview;
    private final Deque<Arena> undo = new ArrayDeque<>();
    private final Deque<Arena> redo = new ArrayDeque<>();
    private final Set<Item> selection = new LinkedHashSet<>();
    private final List<Runnable> changeListeners = new ArrayList<>();
    private final List<Consumer<Arena>> editListeners = new ArrayList<>();
    private Consumer<String> refusals = m -> { };
    private Supplier<Arena> running = () -> null;
    private Supplier<List<RobotView>> live = List::of;
    private String lastRefusal;
    private boolean snap = true;
    private boolean dirty;

    /** @param arena the arena to edit */
    public EditorModel(Arena arena) {
        this.arena = Objects.requireNonNull(arena);
    }

    /** @return the arena as edited */
    public Arena arena() {
        return arena;
    }

    /** @return what to draw: the preview of a gesture in progress, else the arena */
    public Arena shown() {
        return preview != null ? preview : arena;
    }

    /** @param p the arena a gesture in progress would make, or null */
    public void preview(Arena p) {
        preview = p;
        fire();
    }

    /**
     * Replace the arena with another (a new or opened file): clears undo, redo and selection.
     *
     * @param a the arena
     */
    public void load(Arena a) {
        arena = Objects.requireNonNull(a);
        preview = null;
        undo.clear();
        redo.clear();
        selection.clear();
        dirty = false;
        fire();
    }

    /**
     * Apply an edit if the result is possible.
     *
     * @param next the arena after the edit
     * @return true if applied; false if refused (the refusal listener was told why)
     */
    public boolean apply(Arena next) {
        preview = null;
        if (next.equals(arena)) {
            fire();
            return true;
        }
        String problem = ArenaCheck.problem(next, arena, running.get(), running.get() == null ? List.of() : live.get());
        if (problem != null) {
            lastRefusal = problem;
            fire();
            refusals.accept(problem);
            return false;
        }
        undo.push(arena);
        while (undo.size() > UNDO_LIMIT) {
            undo.removeLast();
        }
        redo.clear();
        set(next);
        return true;
    }

    /** @return true if something was undone */
    public boolean undo() {
        if (undo.isEmpty()) {
            return false;
        }
        Arena prev = undo.peek();
        if (ArenaCheck.problem(prev, arena, running.get(), List.of()) != null) {
            refusals.accept("cannot undo that while a run goes on: "
                    + ArenaCheck.problem(prev, arena, running.get(), List.of()));
            return false;
        }
        undo.pop();
        redo.push(arena);
        set(prev);
        return true;
    }

    /** @return true if something was redone */
    public boolean redo() {
        if (redo.isEmpty()) {
            return false;
        }
        Arena next = redo.peek();
        if (ArenaCheck.problem(next, arena, running.get(), List.of()) != null) {
            refusals.accept("cannot redo that while a run goes on: "
                    + ArenaCheck.problem(next, arena, running.get(), List.of()));
            return false;
        }
        redo.pop();
        undo.push(arena);
        set(next);
        return true;
    }

    private void set(Arena next) {
        arena = next;
        dirty = true;
        selection.removeIf(it -> !exists(next, it));
        for (Consumer<Arena> l : editListeners) {
            l.accept(next);
        }
        fire();
    }

    public static boolean exists(Arena a, Item it) {
        int n = switch (it.kind()) {
            case ROBOT -> a.robots().size();
            case WALL -> a.walls().size();
            case LIGHT -> a.lights().size();
            case CAP -> a.caps().size();
        };
        return it.index() < n;
    }

    /** @return true if there is something to undo */
    public boolean canUndo() {
        return !undo.isEmpty();
    }

    /** @return true if there is something to redo */
    public boolean canRedo() {
        return !redo.isEmpty();
    }

    /** @return the selected items, in selection order */
    public Set<Item> selection() {
        return java.util.Collections.unmodifiableSet(selection);
    }

    /** @param items the new selection */
    public void select(Collection<Item> items) {
        selection.clear();
        for (Item it : items) {
            if (exists(arena, it)) {
                selection.add(it);
            }
        }
        fire();
    }

    /** @param it add it to the selection, or remove it if already selected */
    public void toggle(Item it) {
        if (!selection.remove(it)) {
            selection.add(it);
        }
        fire();
    }

    /** Delete the selection (robot start poses are kept). @return true if applied */
    public boolean deleteSelection() {
        List<Item> deletable = selection.stream().filter(i -> i.kind() != Item.Kind.ROBOT).toList();
        if (deletable.isEmpty()) {
            if (!selection.isEmpty()) {
                refuse("a robot's start pose cannot be deleted: an arena needs one; move it instead");
            }
            return false;
        }
        boolean ok = apply(ArenaEdits.delete(arena, deletable));
        if (ok) {
            selection.clear();
            fire();
        }
        return ok;
    }

    /** @param deg rotate the selection counter-clockwise by this many degrees @return true if applied */
    public boolean rotateSelection(double deg) {
        return !selection.isEmpty() && apply(ArenaEdits.rotate(arena, selection, deg));
    }

    /** @param message tell the user an edit was refused */
    public void refuse(String message) {
        lastRefusal = message;
        refusals.accept(message);
        fire();
    }

    /** @return the last refusal's message, or null */
    public String lastRefusal() {
        return lastRefusal;
    }

    /** @return true when positions snap to a 10 mm grid and wall ends to nearby wall ends */
    public boolean snap() {
        return snap;
    }

    /** @param on snapping on or off */
    public void setSnap(boolean on) {
        snap = on;
    }

    /** @return true if edited since loaded or {@link #markSaved() saved} */
    public boolean dirty() {
        return dirty;
    }

    /** The arena has been saved. */
    public void markSaved() {
        dirty = false;
        fire();
    }

    /**
     * The arena as it is being edited, kept aside while something else is shown (a replay) and
     * {@link #restore restored} afterwards.
     *
     * @param arena the arena
     * @param undo its undo steps, newest first
     * @param redo its redo steps, newest first
     * @param dirty whether it has unsaved changes
     */
    public record Kept(Arena arena, List<Arena> undo, List<Arena> redo, boolean dirty) {
        /** Copies the lists. */
        public Kept {
            undo = List.copyOf(undo);
            redo = List.copyOf(redo);
        }
    }

    /** @return the arena with its undo and redo steps and its unsaved mark, to {@link #restore} later */
    public Kept keep() {
        return new Kept(arena, new ArrayList<>(undo), new ArrayList<>(redo), dirty);
    }

    /**
     * @param k what {@link #keep} returned: the arena comes back with its steps and, if it had them, its unsaved
     *     changes
     */
    public void restore(Kept k) {
        arena = k.arena();
        preview = null;
        undo.clear();
        undo.addAll(k.undo());
        redo.clear();
        redo.addAll(k.redo());
        selection.clear();
        dirty = k.dirty();
        fire();
    }

    /** @param l told after every change (edit, selection, preview) */
    public void onChange(Runnable l) {
        changeListeners.add(l);
    }

    /** @param l told of every applied edit, undo and redo, with the new arena (to forward it to a run) */
    public void onEdit(Consumer<Arena> l) {
        editListeners.add(l);
    }

    /** @param l told why an edit was refused */
    public void onRefusal(Consumer<String> l) {
        refusals = l;
    }

    /**
     * @param runningArena the arena of the run going on, or null when there is none
     * @param liveRobots the running robots as last seen
     */
    public void setRun(Supplier<Arena> runningArena, Supplier<List<RobotView>> liveRobots) {
        running = runningArena;
        live = liveRobots;
    }

    private void fire() {
        for (Runnable l : changeListeners) {
            l.run();
        }
    }
}
