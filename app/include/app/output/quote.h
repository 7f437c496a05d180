/* The quotation's header (DOMAIN.md "What the best planners print"): the company that makes the
 * offer (name, address lines, logo) from a settings file, the customer from the project
 * ($.customer), the quote number, date and validity ($.quote). docs/printing.md "Quotation".
 *
 * The company file (JSON): {"name": "...", "address": ["...", ...], "phone": "...",
 * "email": "...", "web": "...", "vat_id": "...", "bank": "...", "logo": "logo.png"}; only
 * "name" is required; the logo (PNG) resolves against the file's folder. The shipped example
 * is assets/company/company.json. */
#ifndef APP_QUOTE_H
#define APP_QUOTE_H

#include "app/design/quantities.h"
#include "app/project/project.h"

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

#define APP_COMPANY_LINES 8

typedef struct app_company {
    char name[128];
    char lines[APP_COMPANY_LINES][128]; /* address lines, then phone, email, web, VAT id, bank */
    int line_count;
    char logo[4096]; /* absolute or relative to the working directory; "" = none */
} app_company;

typedef struct app_quote {
    int has_company;
    app_company company;
    app_customer customer; /* the project's */
    char number[64];       /* the project's $.quote.number, else "Q-YYYYMMDD-XXXX" */
    char date[16];         /* YYYY-MM-DD */
    int valid_days;        /* the project's, else 30 */
    char valid_until[16];  /* date + valid_days */
} app_quote;

/* The default company file: $XDG_CONFIG_HOME/tessera/company.json, else
 * $HOME/.config/tessera/company.json. Returns 0 when neither variable is set. */
int app_company_default_path(char *buf, size_t size);

/* Reads a company file; errors name the file and the problem. */
app_result app_company_read(const char *path, app_company *out, char *err, size_t err_size);

/* The quote of project p on date (YYYY-MM-DD; NULL = today, UTC). company_path NULL: the default
 * file when it exists, else no company block; a path given that cannot be read is an error. The
 * default number is "Q-" + the date's digits + "-" + four hex digits of a hash of the project's
 * name, the same for the same project on the same day. */
app_result app_quote_make(const app_project *p, const char *company_path, const char *date,
                          app_quote *out, char *err, size_t err_size);

/* Writes the quotation of b (app_bom_build, with consumables and labour when wanted) as an XLSX
 * workbook: one sheet "Quotation" with the header, the positions (quantity x unit price as a
 * formula, VAT per line as a formula), the net total, the VAT per rate (SUMIF) and the gross
 * total, amounts formatted in b's currency. Lines in another currency are listed under the
 * totals, not in them. Atomic: a temporary file beside path, renamed when complete. */
app_result app_quote_write_xlsx(const char *path, const app_project *p, const app_quote *q,
                                const app_bom *b, char *err, size_t err_size);

#ifdef __cplusplus
}
#endif
#endif
