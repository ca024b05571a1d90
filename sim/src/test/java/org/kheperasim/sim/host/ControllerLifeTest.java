package org.kheperasim.sim.host;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.EnumSet;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.kheperasim.sim.host.ControllerLife.Event;
import org.kheperasim.sim.host.ControllerLife.Phase;
import org.kheperasim.sim.host.ControllerLife.State;

/**
 * The controller's life as a table: every state a controller can be in, every event, and the state
 * that follows. A row is a state; a column an event; a cell the state after it, written
 * {@code phase[/reason]>status[!]} ({@code !}: its own thread abandoned), or {@code =} when the event
 * changes nothing.
 */
class ControllerLifeTest {

    /** The events of the columns, with the status they carry (FAULT a rule broken, UNWOUND a throw). */
    private static final List<String> COLUMNS = List.of("START", "STOP", "FAULT", "HUNG", "HELPER_HUNG", "DEADLOCKED",
            "UNWOUND", "LEFT_BEHIND");

    private static final String TABLE = """
            state                 | START            | STOP              | FAULT                        | HUNG           | HELPER_HUNG   | DEADLOCKED    | UNWOUND                    | LEFT_BEHIND
            not_started           | running>running  | ended>stopped     | ended/broke_rule>broke_rule  | ended>hung!    | ended>hung    | ended>hung    | ended>failed               | ended>stopped
            running               | =                | stopping>running  | stopping/broke_rule>running  | ended>hung!    | ended>hung    | ended>hung    | ended>failed               | ended>stopped!
            stopping              | =                | =                 | stopping/broke_rule>running  | ended>hung!    | ended>hung    | ended>hung    | ended>failed               | ended>stopped!
            stopping/hung         | =                | =                 | =                            | ended/hung>hung! | ended/hung>hung | =          | ended/hung>hung            | ended/hung>stopped!
            stopping/exceeded_memory | =             | =                 | =                            | ended/exceeded_memory>hung! | ended/exceeded_memory>hung | = | ended/exceeded_memory>exceeded_memory | ended/exceeded_memory>stopped!
            ended>finished        | =                | =                 | =                            | =              | =             | =             | =                          | =
            ended>hung!           | =                | =                 | =                            | =              | =             | =             | =                          | =
            ended/broke_rule>broke_rule | =          | =                 | =                            | =              | =             | =             | =                          | =
            """;

    @Test
    void everyStateAndEventGivesTheStateTheTableSays() {
        List<String> lines = TABLE.lines().filter(l -> !l.isBlank()).toList();
        List<String> header = cells(lines.get(0));
        assertEquals(COLUMNS, header.subList(1, header.size()), "the table's columns");
        EnumSet<Event> covered = EnumSet.noneOf(Event.class);
        EnumSet<Phase> phases = EnumSet.noneOf(Phase.class);
        int checked = 0;
        for (String line : lines.subList(1, lines.size())) {
            List<String> row = cells(line);
            State from = parse(row.get(0));
            phases.add(from.phase());
            for (int c = 1; c < row.size(); c++) {
                Event e = Event.valueOf(header.get(c));
                covered.add(e);
                State after = ControllerLife.next(from, e, argument(e));
                String want = row.get(c);
                String where = row.get(0) + " + " + e;
                if (want.equals("=")) {
                    assertSame(from, after, where + " changes nothing");
                } else {
                    assertEquals(parse(want), after, where);
                }
                checked++;
            }
        }
        assertEquals(EnumSet.allOf(Event.class), covered, "every event has a column");
        assertEquals(EnumSet.allOf(Phase.class), phases, "every phase has a row");
        assertEquals(8 * COLUMNS.size(), checked);
    }

    @Test
    void anEventThatEndsNeedsTheStatusItEndsWith() {
        State running = ControllerLife.next(State.INITIAL, Event.START, null);
        assertThrows(IllegalArgumentException.class, () -> ControllerLife.next(running, Event.FAULT, null));
        assertThrows(IllegalArgumentException.class, () -> ControllerLife.next(running, Event.UNWOUND,
                ControllerStatus.RUNNING));
    }

    @Test
    void theStopIsSignalledOnceAndSettledWhenItsOwnThreadIsOver() {
        AtomicInteger pending = new AtomicInteger();
        ControllerLife life = new ControllerLife(counting(pending));
        assertFalse(life.stopRequested());
        life.on(Event.START);
        assertEquals(0, pending.get(), "starting signals nothing");
        assertTrue(life.on(Event.STOP));
        assertTrue(life.stopRequested());
        assertEquals(1, pending.get());
        assertTrue(life.on(Event.FAULT, ControllerStatus.BROKE_RULE), "a fault after a stop request still decides the end");
        assertFalse(life.on(Event.FAULT, ControllerStatus.EXCEEDED_MEMORY), "only the first fault decides");
        life.signalStop();
        assertEquals(1, pending.get(), "signalled once");
        assertTrue(life.on(Event.UNWOUND, ControllerStatus.STOPPED));
        assertEquals(ControllerStatus.BROKE_RULE, life.status());
        assertTrue(life.ownThreadOver());
        assertFalse(life.ownThreadOver());
        assertEquals(0, pending.get(), "settled once");
    }

    @Test
    void aControllerThatEndsByItselfSignalsNothingAndAStopBeforeItsStartNeither() {
        AtomicInteger pending = new AtomicInteger();
        ControllerLife finished = new ControllerLife(counting(pending));
        finished.on(Event.START);
        finished.on(Event.UNWOUND, ControllerStatus.FINISHED);
        finished.ownThreadOver();
        ControllerLife neverRan = new ControllerLife(counting(pending));
        neverRan.on(Event.STOP);
        assertEquals(ControllerStatus.STOPPED, neverRan.status());
        assertEquals(0, pending.get());
        // Its threads still have to unwind after it has ended: the owner signals then.
        finished.signalStop();
        assertEquals(1, pending.get());
    }

    @Test
    @Timeout(value = 60, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
    void faultsFromManyThreadsAtOnceDecideOneEnd() throws InterruptedException {
        ControllerStatus[] faults = {ControllerStatus.BROKE_RULE, ControllerStatus.EXCEEDED_MEMORY, ControllerStatus.HUNG};
        for (int round = 0; round < 200; round++) {
            AtomicInteger pending = new AtomicInteger();
            ControllerLife life = new ControllerLife(counting(pending));
            life.on(Event.START);
            CountDownLatch go = new CountDownLatch(1);
            List<Thread> threads = new ArrayList<>();
            Map<ControllerStatus, Boolean> won = new java.util.concurrent.ConcurrentHashMap<>();
            for (ControllerStatus f : faults) {
                Thread t = new Thread(() -> {
                    try {
                        go.await();
                    } catch (InterruptedException e) {
                        return;
                    }
                    won.put(f, life.on(Event.FAULT, f));
                });
                t.start();
                threads.add(t);
            }
            go.countDown();
            for (Thread t : threads) {
                t.join(TimeUnit.SECONDS.toMillis(10));
            }
            List<ControllerStatus> winners = won.entrySet().stream().filter(Map.Entry::getValue).map(Map.Entry::getKey).toList();
            assertEquals(1, winners.size(), "exactly one fault decides: " + won);
            life.on(Event.UNWOUND, ControllerStatus.FAILED);
            assertEquals(winners.get(0), life.status(), "the winner is the end");
            assertEquals(1, pending.get(), "signalled once");
        }
    }

    // ------------------------------------------------------------------ the table's notation

    private static ControllerStatus argument(Event e) {
        return switch (e) {
            case FAULT -> ControllerStatus.BROKE_RULE;
            case UNWOUND -> ControllerStatus.FAILED;
            default -> null;
        };
    }

    private static List<String> cells(String line) {
        List<String> out = new ArrayList<>();
        for (String c : line.split("\\|")) {
            out.add(c.trim());
        }
        return out;
    }

    /** {@code phase[/reason][>status][!]}; the status defaults from the phase. */
    private static State parse(String text) {
        boolean abandoned = text.endsWith("!");
        String t = abandoned ? text.substring(0, text.length() - 1) : text;
        String status = null;
        int gt = t.indexOf('>');
        if (gt >= 0) {
            status = t.substring(gt + 1);
            t = t.substring(0, gt);
        }
        String reason = null;
        int slash = t.indexOf('/');
        if (slash >= 0) {
            reason = t.substring(slash + 1);
            t = t.substring(0, slash);
        }
        Phase phase = Phase.valueOf(t.toUpperCase(Locale.ROOT));
        ControllerStatus st = status != null ? ControllerStatus.valueOf(status.toUpperCase(Locale.ROOT))
                : phase == Phase.NOT_STARTED ? ControllerStatus.NOT_STARTED : ControllerStatus.RUNNING;
        return new State(phase, reason == null ? null : ControllerStatus.valueOf(reason.toUpperCase(Locale.ROOT)), st,
                abandoned);
    }

    private static ControllerLife.StopSignal counting(AtomicInteger pending) {
        return new ControllerLife.StopSignal() {
            @Override
            public void requested() {
                pending.incrementAndGet();
            }

            @Override
            public void settled() {
                pending.decrementAndGet();
            }
        };
    }
}
