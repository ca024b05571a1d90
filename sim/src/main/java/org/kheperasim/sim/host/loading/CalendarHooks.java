package org.kheperasim.sim.host.loading;

import java.util.Calendar;
import java.util.Locale;
import java.util.TimeZone;
import org.kheperasim.sim.host.SimClock;

/**
 * Where controller code's {@code Calendar.getInstance(...)} goes instead (see {@link CallTargets}):
 * the same calendar, set to the simulated clock, as {@code System.currentTimeMillis()} reads it.
 * The JDK's own {@code getInstance} reads the wall clock inside the JDK, where the rewrite of
 * {@code currentTimeMillis} does not reach.
 */
public final class CalendarHooks {
    private CalendarHooks() {
    }

    /** Replaces {@link Calendar#getInstance()}. */
    public static Calendar getInstance() {
        return now(Calendar.getInstance());
    }

    /** Replaces {@link Calendar#getInstance(TimeZone)}. */
    public static Calendar getInstance(TimeZone zone) {
        return now(Calendar.getInstance(zone));
    }

    /** Replaces {@link Calendar#getInstance(Locale)}. */
    public static Calendar getInstance(Locale locale) {
        return now(Calendar.getInstance(locale));
    }

    /** Replaces {@link Calendar#getInstance(TimeZone, Locale)}. */
    public static Calendar getInstance(TimeZone zone, Locale locale) {
        return now(Calendar.getInstance(zone, locale));
    }

    private static Calendar now(Calendar c) {
        c.setTimeInMillis(SimClock.currentTimeMillis());
        return c;
    }
}
