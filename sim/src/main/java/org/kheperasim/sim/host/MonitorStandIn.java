package org.kheperasim.sim.host;

/**
 * What a contained controller's code locks in place of an object it does not own (an interned
 * string, an enum constant, a class of the platform): the controller class loader's stand-in
 * ({@code host.loading.Monitors}). The host's messages about a lockstep that waits name the type of
 * the object locked, never the stand-in.
 */
public interface MonitorStandIn {
    /** @return the binary name of the type of the object this stands in for */
    String standsForType();

    /**
     * @param monitor an object a controller locks, waits on or notifies, or a stand-in (not null)
     * @return the binary name of the type of the object a stand-in stands for, else of {@code monitor}'s own type
     */
    static String typeName(Object monitor) {
        return monitor instanceof MonitorStandIn s ? s.standsForType() : monitor.getClass().getName();
    }
}
