/* pfx C ABI v1 — importers. Reserved: the factory id is fixed now so hosts can ask for it; the
 * structs arrive with the OBJ importer and are published under this id then. Until a plugin
 * implements it, get_factory(PFX_IMPORTERS_FACTORY_ID) returns NULL. */
#ifndef PFX_IMPORTER_H
#define PFX_IMPORTER_H

#define PFX_IMPORTERS_FACTORY_ID "pfx.importers/1"

#endif /* PFX_IMPORTER_H */
